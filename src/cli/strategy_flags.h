#pragma once
// The strategy flags of `prt render` and `prt simulate`, built from the registry's rows
// (balance/registry.h): --strategy, and one flag per option a row declares, with its help,
// range and default. Adding an option to a row adds its flag to both commands.

#include <CLI/CLI.hpp>
#include <map>
#include <optional>
#include <string>

#include "balance/registry.h"

namespace prt::cli {

struct StrategyFlags {
  std::optional<std::string> strategy;   // --strategy; absent: kDefaultStrategy
  std::map<std::string, double> values;  // by flag name, preset to the defaults
  std::string name() const { return strategy.value_or(kDefaultStrategy); }
};

// Adds --strategy and the option flags to `cmd`, in `group`, bound to `flags`.
void addStrategyFlags(CLI::App& cmd, StrategyFlags& flags, const std::string& group);

// The options the flags hold. Throws InputError naming the flag and its range for a value
// out of range (a fraction for a whole-number option included), and for an unknown strategy.
StrategyOptions strategyOptionsFrom(const StrategyFlags& flags);

}  // namespace prt::cli
