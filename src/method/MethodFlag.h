// Building a method's flags (MethodUnit::flags): each bound into a field of its own settings.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <utility>

#include "src/method/MethodUnit.h"
#include "src/options/Options.h"

namespace hemirad {

// `name` bound into `field`, converted as CLI11 converts a bound option; the default shown is
// `defaultText`, else the option table's, else `field`'s initial value.
template <class T>
MethodFlag bindFlag(const std::string& name, T& field, std::string defaultText = {}) {
  return {name, [&field](const CLI::Option& o) { o.results(field); }, std::move(defaultText),
          CLI::detail::checked_to_string<T, T>(field)};
}

// `name` read as text and turned into `field` by `parse` (names of enumerations).
template <class T, class Parse>
MethodFlag parseFlag(const std::string& name, T& field, Parse parse, std::string defaultText) {
  return {
      name, [&field, parse](const CLI::Option& o) { field = parse(o.as<std::string>()); }, std::move(defaultText), {}};
}

// A switch: `set` runs when it is given.
template <class Set>
MethodFlag switchFlag(const std::string& name, Set set) {
  return {name, [set](const CLI::Option&) { set(); }, {}, {}};
}

// --hemisphere, one projection (`all` is validate's).
inline MethodFlag projectionFlag(Projection& field) {
  return {"--hemisphere",
          [&field](const CLI::Option& o) { field = options::oneProjection(o.as<int>()); },
          options::defaultText("--hemisphere"),
          {}};
}

// One of solve's own flags (SolveOptions) that this method takes: others refuse it.
inline MethodFlag acceptFlag(const std::string& name) { return {name, {}, {}, {}}; }

}  // namespace hemirad
