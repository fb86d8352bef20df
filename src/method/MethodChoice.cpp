#include "src/method/MethodChoice.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <algorithm>

#include "src/base/Error.h"
#include "src/method/Registry.h"
#include "src/options/Options.h"

namespace hemirad {

namespace {

bool takes(MethodUnit& m, const std::string& flag) {
  const std::vector<MethodFlag> flags = m.flags();
  return std::any_of(flags.begin(), flags.end(), [&](const MethodFlag& f) { return f.name == flag; });
}

}  // namespace

MethodChoice::MethodChoice() : MethodChoice(makeMethods()) {}

MethodChoice::MethodChoice(std::vector<std::unique_ptr<MethodUnit>> methods) : methods_(std::move(methods)) {}

std::vector<std::string> MethodChoice::names() const {
  std::vector<std::string> names;
  for (const auto& m : methods_) names.push_back(m->name());
  return names;
}

std::vector<std::string> MethodChoice::flagNames() const {
  std::vector<std::string> names;
  for (const options::Flag& f : options::table())
    if (std::any_of(methods_.begin(), methods_.end(), [&](const auto& m) { return takes(*m, f.name); }))
      names.push_back(f.name);
  return names;
}

void MethodChoice::declareFlags(CLI::App* solve) const {
  for (const std::string& name : flagNames()) {
    if (solve->get_option_no_throw(name)) continue;  // solve's own, as --camera-path
    std::vector<MethodFlag> binders;
    for (const auto& m : methods_)
      for (MethodFlag& f : m->flags())
        if (f.name == name && f.bind) binders.push_back(std::move(f));
    if (binders.empty()) continue;  // solve's own (--camera-path), added by the command after
    options::declare(solve, name, binders.front().defaultText, binders.front().value);
  }
}

MethodUnit& MethodChoice::choose(const std::string& name, const CLI::App& solve) const {
  auto chosen = std::find_if(methods_.begin(), methods_.end(), [&](const auto& m) { return m->name() == name; });
  if (chosen == methods_.end())
    throw InputError(fmt::format("--method {}: not one of {}", name, fmt::join(names(), ", ")));
  MethodUnit& method = **chosen;
  for (const std::string& flag : flagNames()) {
    const CLI::Option* option = solve.get_option_no_throw(flag);
    if (!option || !*option || takes(method, flag)) continue;
    std::vector<std::string> takers;
    for (const auto& m : methods_)
      if (takes(*m, flag)) takers.push_back(m->name());
    throw InputError(fmt::format("{} is for --method {}, not {}", flag, fmt::join(takers, " or "), name));
  }
  for (const MethodFlag& f : method.flags())
    if (f.bind && *solve.get_option(f.name)) f.bind(*solve.get_option(f.name));
  return method;
}

}  // namespace hemirad
