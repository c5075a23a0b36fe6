// makeStrategy: a name -> factory table. Adding a strategy is one line here.

#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "balance/blocks.h"
#include "balance/factoring.h"
#include "balance/guided.h"
#include "balance/hybrid.h"
#include "balance/reservoir.h"
#include "balance/scatter.h"
#include "balance/self_scheduling.h"
#include "balance/strategy.h"
#include "core/input_error.h"

namespace prt {
namespace {

using Factory = std::function<std::unique_ptr<Strategy>(const StrategyOptions&)>;

const std::vector<std::pair<std::string, Factory>>& factories() {
  static const std::vector<std::pair<std::string, Factory>> table = {
      {"scatter", [](const StrategyOptions&) { return std::make_unique<ScatterStrategy>(); }},
      {"hybrid", [](const StrategyOptions&) { return std::make_unique<HybridStrategy>(); }},
      {"reservoir",
       [](const StrategyOptions& o) {
         return std::make_unique<ReservoirStrategy>(o.initialPercent);
       }},
      {"reservoir-scatter",
       [](const StrategyOptions& o) {
         return std::make_unique<ReservoirStrategy>(o.initialPercent, /*interleaved=*/true);
       }},
      {"blocks", [](const StrategyOptions&) { return std::make_unique<BlocksStrategy>(); }},
      {"self",
       [](const StrategyOptions& o) { return std::make_unique<SelfSchedulingStrategy>(o.chunk); }},
      {"guided", [](const StrategyOptions&) { return std::make_unique<GuidedStrategy>(); }},
      {"factoring", [](const StrategyOptions&) { return std::make_unique<FactoringStrategy>(); }},
  };
  return table;
}

}  // namespace

void validateStrategyOptions(const StrategyOptions& options) {
  if (!(std::isfinite(options.initialPercent) && options.initialPercent > 0 &&
        options.initialPercent <= 100)) {
    throw InputError("initial percentage " + std::to_string(options.initialPercent) +
                     " is out of range; it must be in (0, 100]");
  }
  if (options.chunk == 0) throw InputError("chunk must be at least 1 task");
}

std::vector<std::string> strategyNames() {
  std::vector<std::string> names;
  for (const auto& entry : factories()) names.push_back(entry.first);
  return names;
}

std::unique_ptr<Strategy> makeStrategy(const std::string& name, const StrategyOptions& options) {
  validateStrategyOptions(options);
  for (const auto& [known, factory] : factories()) {
    if (known == name) return factory(options);
  }
  std::string valid;
  for (const std::string& known : strategyNames()) {
    valid += (valid.empty() ? "" : ", ") + known;
  }
  throw InputError("unknown strategy '" + name + "'; valid strategies: " + valid);
}

}  // namespace prt
