#pragma once
// The strategy registry: one row per strategy, naming it, saying its kind, whether it reads
// the speed index, the options it takes (each with its help, range and default) and how to
// make it. The command line, `prt simulate` and the experiments build their flags and their
// lists of strategies from these rows; the default strategy is named here, once.
// Read-only tables; thread-safe.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "balance/strategy.h"

namespace prt {

// The strategy the tools use when none is named: the best one measured (docs/results.md).
inline constexpr const char* kDefaultStrategy = "adaptive";

enum class StrategyKind {
  Static,    // splits every task at the start
  Dynamic,   // hands tasks out (or moves them) as workers ask, by fixed rules
  Adaptive,  // sizes its hand-outs from the speeds it measures as results come back
};
const char* strategyKindName(StrategyKind kind);  // "static", "dynamic", "adaptive"

// One option: a field of StrategyOptions with its command-line flag, help and range.
// The largest whole-number option value (2^53: every whole number up to it is a double).
inline constexpr double kMaxWholeOption = 9007199254740992.0;

struct StrategyOption {
  std::string flag;  // "initial-percent" is --initial-percent
  std::string help;
  std::variant<double StrategyOptions::*, uint64_t StrategyOptions::*> field;
  double min = 0, max = 0;
  bool minIncluded = true, maxIncluded = true;

  double get(const StrategyOptions& options) const;
  void set(StrategyOptions& options, double value) const;
  double defaultValue() const { return get(StrategyOptions{}); }
  bool isInteger() const { return std::holds_alternative<uint64_t StrategyOptions::*>(field); }
  bool accepts(double value) const;
  std::string rangeText() const;  // "(0, 100]", ">= 1"
};

struct StrategyRow {
  std::string name;
  StrategyKind kind = StrategyKind::Static;
  std::string summary;          // one line for the help text
  bool readsSpeedIndex = true;  // false: it starts as well without a speed-index run
  std::vector<StrategyOption> options;
  std::function<std::unique_ptr<Strategy>(const StrategyOptions&)> make;
};

// Checks a strategy's name and options as makeStrategy() would, without building it: throws
// InputError for an unknown name (listing the valid ones) or an option out of its range.
void validateStrategy(const std::string& name, const StrategyOptions& options);

// Every row, in the order the help text lists them.
const std::vector<StrategyRow>& strategyRows();
// The row named `name`; an unknown name throws InputError listing the valid ones.
const StrategyRow& strategyRow(const std::string& name);
// Every option of every row, each once (rows share an option by its flag), in row order.
std::vector<StrategyOption> strategyOptions();
// The names of the strategies that take option `flag`, in row order.
std::vector<std::string> strategiesTaking(const std::string& flag);
// Whether the workers run a speed index before `strategy` starts, when the user does not say:
// no for the adaptive strategies, which learn speeds as they go (they start at once), yes
// for the rest, as the paper's runs do.
bool runsSpeedIndexByDefault(const std::string& strategy);
// "name (kind) - summary" lines for help texts.
std::string strategyHelp();

}  // namespace prt
