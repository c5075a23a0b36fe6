#include "cli/strategy_flags.h"

#include "cli/flag_checks.h"
#include "core/input_error.h"

namespace prt::cli {
namespace {

// The option's own range, checked on the text given, so that the message quotes it.
CLI::Validator strategyValue(const StrategyOption& option) {
  return CLI::Validator(
      [option](std::string& text) -> std::string {
        double value = 0;
        if (detail::parseNumber(text, value) && option.accepts(value)) return {};
        return std::string("must be ") + (option.isInteger() ? "a whole number " : "a number ") +
               (option.rangeText().front() == '>' ? "" : "in ") + option.rangeText() +
               "; found '" + text + "'";
      },
      option.rangeText());
}

}  // namespace

void addStrategyFlags(CLI::App& cmd, StrategyFlags& flags, const std::string& group) {
  cmd.add_option("--strategy", flags.strategy,
                 "Load balancing (default " + std::string(kDefaultStrategy) + "):\n" +
                     strategyHelp())
      ->group(group);
  for (const StrategyOption& option : strategyOptions()) {
    double& value = flags.values[option.flag];  // map nodes stay put: safe to bind
    value = option.defaultValue();
    std::string users;
    for (const std::string& name : strategiesTaking(option.flag)) {
      users += (users.empty() ? "" : ", ") + name;
    }
    CLI::Option* flag = cmd.add_option("--" + option.flag, value,
                                       users + ": " + option.help + ", " + option.rangeText())
                            ->capture_default_str()
                            ->group(group)
                            ->check(strategyValue(option));
    if (option.isInteger()) flag->type_name("INT");
  }
}

StrategyOptions strategyOptionsFrom(const StrategyFlags& flags) {
  strategyRow(flags.name());  // an unknown name lists the valid ones
  StrategyOptions options;
  for (const StrategyOption& option : strategyOptions()) {
    const auto found = flags.values.find(option.flag);
    if (found == flags.values.end()) continue;
    if (!option.accepts(found->second)) {
      throw InputError("--" + option.flag + " " + std::to_string(found->second) +
                       " is out of range; it must be " +
                       (option.isInteger() ? "a whole number " : "") + option.rangeText());
    }
    option.set(options, found->second);
  }
  return options;
}

}  // namespace prt::cli
