// The strategy rows. Adding a strategy is one row here.

#include "balance/registry.h"

#include <cmath>
#include <limits>
#include <type_traits>
#include <string>
#include <utility>

#include "balance/adaptive_factoring.h"
#include "balance/adaptive_reservoir.h"
#include "balance/awf.h"
#include "balance/blocks.h"
#include "balance/factoring.h"
#include "balance/frame_strategy.h"
#include "balance/guided.h"
#include "balance/hybrid.h"
#include "balance/reservoir.h"
#include "balance/scatter.h"
#include "balance/self_scheduling.h"
#include "balance/stealing.h"
#include "balance/weighted_scatter.h"
#include "core/input_error.h"

namespace prt {
namespace {

std::string number(double v) {
  std::string s = std::to_string(v);
  while (s.find('.') != std::string::npos && (s.back() == '0' || s.back() == '.')) {
    const bool dot = s.back() == '.';
    s.pop_back();
    if (dot) break;
  }
  return s;
}

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

const StrategyOption kInitialPercent{
    "initial-percent", "share of the tasks handed out at the start, the rest kept in the reservoir",
    &StrategyOptions::initialPercent, 0, 100, false, true};
const StrategyOption kChunk{"chunk", "tasks per hand-out", &StrategyOptions::chunk, 1, kUnbounded};
const StrategyOption kMinChunk{"min-chunk", "the smallest hand-out or steal, in tasks",
                               &StrategyOptions::minChunk, 1, kUnbounded};
const StrategyOption kFirstPercent{"first-percent",
                                   "share of the image handed out at the start, before any speed "
                                   "is measured",
                                   &StrategyOptions::firstPercent, 0, 100, false, true};
const StrategyOption kReservePercent{
    "reserve-percent", "share of the expected remaining time each hand-out leaves in the reserve",
    &StrategyOptions::reservePercent, 0, 100, true, false};

template <typename S, typename... Args>
std::unique_ptr<Strategy> make(Args&&... args) {
  return std::make_unique<S>(std::forward<Args>(args)...);
}

const std::vector<StrategyRow>& rows() {
  using K = StrategyKind;
  using O = StrategyOptions;
  static const std::vector<StrategyRow> table = {
      {"scatter", K::Static, "pixel i to worker i mod c", false, {},
       [](const O&) { return make<ScatterStrategy>(); }},
      {"scatter-weighted", K::Static,
       "scatter with shares weighted by the speed index (interleaved stretches)", true, {},
       [](const O&) { return make<WeightedScatterStrategy>(); }},
      {"hybrid", K::Dynamic, "scatter, then diffusion towards the average queue", false, {},
       [](const O&) { return make<HybridStrategy>(); }},
      {"hybrid-weighted", K::Dynamic,
       "weighted scatter, then diffusion towards speed-weighted queues", true, {},
       [](const O&) { return make<HybridStrategy>(/*speedWeighted=*/true); }},
      {"reservoir", K::Dynamic, "the paper's reservoir algorithm, in scan-line order", true,
       {kInitialPercent}, [](const O& o) { return make<ReservoirStrategy>(o.initialPercent); }},
      {"reservoir-scatter", K::Dynamic, "the reservoir over an interleaved task order", true,
       {kInitialPercent},
       [](const O& o) { return make<ReservoirStrategy>(o.initialPercent, /*interleaved=*/true); }},
      {"adaptive", K::Adaptive,
       "a reservoir sized by measured speeds so that all finish together; steals at the end",
       false, {kFirstPercent, kReservePercent, kMinChunk},
       [](const O& o) {
         return make<AdaptiveReservoirStrategy>(o.firstPercent, o.reservePercent, o.minChunk);
       }},
      {"blocks", K::Static, "one contiguous block per worker", false, {},
       [](const O&) { return make<BlocksStrategy>(); }},
      {"frames", K::Dynamic,
       "whole frames of a sequence to whole workers, as render farms do (a still: to one)",
       false, {}, [](const O&) { return make<FrameStrategy>(); }},
      {"self", K::Dynamic, "self-scheduling with a fixed chunk", false, {kChunk},
       [](const O& o) { return make<SelfSchedulingStrategy>(o.chunk); }},
      {"guided", K::Dynamic, "guided self-scheduling, ceil(R / c)", false, {},
       [](const O&) { return make<GuidedStrategy>(); }},
      {"factoring", K::Dynamic, "weighted factoring, weights from the speed index", true, {},
       [](const O&) { return make<FactoringStrategy>(); }},
      {"awf-b", K::Adaptive, "adaptive weighted factoring, weights per batch (Carino & Banicescu)",
       false, {kMinChunk},
       [](const O& o) { return make<AwfStrategy>(AwfStrategy::Variant::Batch, o.minChunk); }},
      {"awf-c", K::Adaptive, "adaptive weighted factoring, weights per chunk", false, {kMinChunk},
       [](const O& o) { return make<AwfStrategy>(AwfStrategy::Variant::Chunk, o.minChunk); }},
      {"af", K::Adaptive, "adaptive factoring, from the mean and variance of task times", false,
       {kMinChunk}, [](const O& o) { return make<AdaptiveFactoringStrategy>(o.minChunk); }},
      {"stealing", K::Dynamic, "even interleaved shares; an idle worker steals half the fullest queue",
       false, {kMinChunk}, [](const O& o) { return make<StealingStrategy>(o.minChunk); }},
  };
  return table;
}

}  // namespace

const char* strategyKindName(StrategyKind kind) {
  switch (kind) {
    case StrategyKind::Static:
      return "static";
    case StrategyKind::Dynamic:
      return "dynamic";
    case StrategyKind::Adaptive:
      return "adaptive";
  }
  return "?";
}

double StrategyOption::get(const StrategyOptions& options) const {
  return std::visit([&](auto member) { return static_cast<double>(options.*member); }, field);
}

void StrategyOption::set(StrategyOptions& options, double value) const {
  std::visit(
      [&](auto member) {
        using T = std::remove_reference_t<decltype(options.*member)>;
        options.*member = static_cast<T>(value);
      },
      field);
}

bool StrategyOption::accepts(double value) const {
  if (!std::isfinite(value)) return false;
  if (isInteger() && value != std::floor(value)) return false;
  if (isInteger() && value > kMaxWholeOption) return false;  // beyond: not held exactly
  const bool aboveMin = minIncluded ? value >= min : value > min;
  const bool belowMax = maxIncluded ? value <= max : value < max;
  return aboveMin && belowMax;
}

std::string StrategyOption::rangeText() const {
  if (std::isinf(max) && !isInteger()) return ">= " + number(min);
  std::string text = minIncluded ? "[" : "(";
  text.append(number(min)).append(", ");
  text.append(number(std::isinf(max) ? kMaxWholeOption : max));
  text.append(maxIncluded || std::isinf(max) ? "]" : ")");
  return text;
}

const std::vector<StrategyRow>& strategyRows() {
  return rows();
}

std::vector<std::string> strategyNames() {
  std::vector<std::string> names;
  for (const StrategyRow& row : rows()) names.push_back(row.name);
  return names;
}

const StrategyRow& strategyRow(const std::string& name) {
  for (const StrategyRow& row : rows()) {
    if (row.name == name) return row;
  }
  std::string valid;
  for (const std::string& known : strategyNames()) valid += (valid.empty() ? "" : ", ") + known;
  throw InputError("unknown strategy '" + name + "'; valid strategies: " + valid);
}

std::vector<StrategyOption> strategyOptions() {
  std::vector<StrategyOption> out;
  for (const StrategyRow& row : rows()) {
    for (const StrategyOption& option : row.options) {
      bool seen = false;
      for (const StrategyOption& o : out) seen = seen || o.flag == option.flag;
      if (!seen) out.push_back(option);
    }
  }
  return out;
}

std::vector<std::string> strategiesTaking(const std::string& flag) {
  std::vector<std::string> names;
  for (const StrategyRow& row : rows()) {
    for (const StrategyOption& option : row.options) {
      if (option.flag == flag) names.push_back(row.name);
    }
  }
  return names;
}

bool runsSpeedIndexByDefault(const std::string& strategy) {
  return strategyRow(strategy).kind != StrategyKind::Adaptive;
}

std::string strategyHelp() {
  std::string out;
  for (const StrategyRow& row : rows()) {
    out += "  " + row.name + " (" + strategyKindName(row.kind) + ")" +
           (row.name == kDefaultStrategy ? ", the default" : "") + ": " + row.summary + "\n";
  }
  return out;
}

void validateStrategyOptions(const StrategyOptions& options) {
  for (const StrategyOption& option : strategyOptions()) {
    const double value = option.get(options);
    if (!option.accepts(value)) {
      throw InputError("--" + option.flag + " " + number(value) + " is out of range; it must be " +
                       (option.rangeText().front() == '>' ? "" : "in ") + option.rangeText());
    }
  }
}

void validateStrategy(const std::string& name, const StrategyOptions& options) {
  validateStrategyOptions(options);
  strategyRow(name);
}

std::unique_ptr<Strategy> makeStrategy(const std::string& name, const StrategyOptions& options) {
  validateStrategy(name, options);
  return strategyRow(name).make(options);
}

}  // namespace prt
