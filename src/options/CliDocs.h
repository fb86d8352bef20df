// docs/cli.md, written from the commands as built (their flags from the option table), so it
// cannot drift from --help: `hemirad docs cli > docs/cli.md`; a test compares the two.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace hemirad::options {

std::string markdown(const CLI::App& app);

}  // namespace hemirad::options
