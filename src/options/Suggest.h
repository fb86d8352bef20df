// Bad command lines: an unknown flag or subcommand is one error line naming the closest valid
// name (CLI11 names only the unknown one), and parse errors print as every other input error.
#pragma once
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hemirad::options {

// Edits (insert, delete, substitute, swap neighbours) turning a into b.
std::size_t editDistance(std::string_view a, std::string_view b);
// The candidate nearest `name` if near enough to be a typing slip (or a prefix of it); else "".
std::string closest(const std::string& name, const std::vector<std::string>& candidates);
// The first unknown subcommand or flag of `args` (argv without the program) as an error
// message with a suggestion; "" when every name is known.
std::string unknownName(CLI::App& app, const std::vector<std::string>& args);
// Parses; prints help or version and returns 0, or prints one `hemirad: error:` line and
// returns kExitInputError; nullopt when the command should run.
std::optional<int> parse(CLI::App& app, int argc, char** argv);

}  // namespace hemirad::options
