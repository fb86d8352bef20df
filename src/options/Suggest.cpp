#include "src/options/Suggest.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>

#include "src/base/Error.h"
#include "src/options/Options.h"

namespace hemirad::options {

std::size_t editDistance(std::string_view a, std::string_view b) {
  // Optimal string alignment: Levenshtein plus transposed neighbours, three rows.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

std::string closest(const std::string& name, const std::vector<std::string>& candidates) {
  auto bare = [](const std::string& s) {
    return std::string_view(s).substr(std::min(s.find_first_not_of('-'), s.size()));
  };
  const std::string_view n = bare(name);
  const std::size_t slack = std::max<std::size_t>(2, n.size() / 3);
  std::string best;
  std::size_t bestDistance = slack + 1;
  for (const std::string& c : candidates) {
    const std::string_view b = bare(c);
    const std::size_t d = n.size() >= 3 && b.starts_with(n) ? 1 : editDistance(n, b);
    if (d < bestDistance) best = c, bestDistance = d;
  }
  return best;
}

namespace {

std::vector<std::string> flagNames(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::Option* o : cmd.get_options())
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
  return names;
}

bool inTable(const std::string& name) {
  return std::any_of(table().begin(), table().end(), [&](const Flag& f) { return f.name == name; });
}

// The subcommand's name: the first argument that is neither a flag nor the value of one of the
// app's own flags (`hemirad-bench --elements 10000 experiment`: 10000 is --elements' value).
std::vector<std::string>::const_iterator subcommandName(CLI::App& app, const std::vector<std::string>& args) {
  for (auto a = args.begin(); a != args.end(); ++a) {
    if (!a->starts_with("-")) return a;
    const CLI::Option* o = a->find('=') == std::string::npos ? app.get_option_no_throw(*a) : nullptr;
    if (o && o->get_items_expected_max() > 0 && a + 1 != args.end()) ++a;
  }
  return args.end();
}

}  // namespace

std::string unknownName(CLI::App& app, const std::vector<std::string>& args) {
  CLI::App* cmd = &app;
  std::string command = app.get_name();
  auto arg = args.begin();
  if (!app.get_subcommands({}).empty()) {
    arg = subcommandName(app, args);
    if (arg == args.end()) return "";
    std::vector<std::string> names;  // the listed subcommands
    cmd = nullptr;
    for (CLI::App* s : app.get_subcommands({})) {
      if (!s->get_group().empty()) names.push_back(s->get_name());
      if (s->get_name() == *arg) cmd = s;
    }
    if (!cmd) {
      const std::string near = closest(*arg, names);
      return fmt::format("unknown subcommand '{}'{} (the subcommands: {})", *arg,
                         near.empty() ? "" : fmt::format(": did you mean {}?", near), fmt::join(names, ", "));
    }
    command += " " + *arg++;
  }
  for (; arg != args.end() && *arg != "--"; ++arg) {
    if (!arg->starts_with("--")) continue;
    const std::string name = arg->substr(0, arg->find('='));
    if (cmd->get_option_no_throw(name)) continue;
    const std::string near = closest(name, flagNames(*cmd));
    if (!near.empty()) return fmt::format("unknown flag {} for {}: did you mean {}?", name, command, near);
    if (inTable(name)) return fmt::format("{} is not a flag of {} ({} --help lists them)", name, command, command);
    return fmt::format("unknown flag {} for {} ({} --help lists them)", name, command, command);
  }
  return "";
}

std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (std::string message = unknownName(app, args); !message.empty()) throw InputError(message);
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitInputError;
  } catch (const InputError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitInputError;
  }
  return std::nullopt;
}

}  // namespace hemirad::options
