// Every flag of every command, declared once: name, value, check and help. A command picks the
// flags it takes by name and binds each to a field of its own options struct, so a flag means
// the same and is checked the same wherever it appears. Defaults are the commands' own (their
// structs' initial values), shown in --help and docs/cli.md. This library needs no image,
// validate or viewer library: the lean hemirad-bench links it.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "src/solver/Projection.h"

namespace hemirad {
struct ProgressiveSettings;
}

namespace hemirad::options {

struct Flag {
  Flag(std::string name, std::string value, std::string help, CLI::Validator check, std::string defaultText = {})
      : name(std::move(name)),
        value(std::move(value)),
        help(std::move(help)),
        check(std::move(check)),
        defaultText(std::move(defaultText)) {}
  std::string name;   // "--texel-size"
  std::string value;  // what it takes, "SIZE"; empty for a switch
  std::string help;
  CLI::Validator check;     // the one check of its values (each item of a list)
  std::string defaultText;  // shown instead of the bound field's value (enumerations)
};

const std::vector<Flag>& table();
const Flag& flag(const std::string& name);  // std::logic_error for a name not in the table

namespace detail {
template <class T>
struct IsList : std::false_type {};
template <class T>
struct IsList<std::vector<T>> : std::true_type {};
CLI::Option* finish(CLI::Option* option, const Flag& flag, bool list, const std::string& defaultText);
}  // namespace detail

// Adds the table's flag `name` to `cmd`, storing into `target`; a vector takes a comma list.
// `defaultText` describes a default the field does not hold until after parsing.
template <class T>
CLI::Option* add(CLI::App* cmd, const std::string& name, T& target, const std::string& defaultText = {}) {
  const Flag& f = flag(name);
  return detail::finish(cmd->add_option(f.name, target, f.help), f, detail::IsList<T>::value, defaultText);
}
CLI::Option* addSwitch(CLI::App* cmd, const std::string& name, bool& target);
// Adds the table's flag `name` to `cmd` unbound: whoever takes it reads its value after parsing
// (CLI::Option::results), as the radiosity methods do (src/method/MethodUnit.h). The default
// shown: `defaultText`, else the table's, else `value` (the taker's initial value).
CLI::Option* declare(CLI::App* cmd, const std::string& name, const std::string& defaultText, const std::string& value);
// One of `names` (any case), for a flag whose names are known only above this library (--method).
CLI::Validator oneOfNames(const std::vector<std::string>& names);
// What --hemisphere all stores (validate: every projection); a name stores its Projection.
constexpr int kAllProjections = -1;
// The projection stored for a command that takes one (solve, bench): InputError for `all`.
Projection oneProjection(int stored);

// Presets (src/solver/Presets.h). The default shown for a flag a preset sets (--hemisphere,
// --item-subdiv, --item-res, --shoot-level): the default preset's value, "auto (preset fast)".
std::string defaultText(const std::string& flag);
// `p` from preset `name`, but keeping the values of the flags `given` says were given: flags given
// beside --preset override it, whichever order they come in and whichever is stored first.
void applyPreset(ProgressiveSettings& p, const std::string& name, const std::function<bool(const std::string&)>& given);
// --preset, --hemisphere, --item-subdiv, --item-res and (with `shootLevel`) --shoot-level, bound to
// `p` (bench, view, experiment, compare-methods; solve's progressive method binds its own).
void addItemPlan(CLI::App* cmd, ProgressiveSettings& p, bool shootLevel = true);

}  // namespace hemirad::options
