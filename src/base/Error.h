// Errors the user can fix (bad files, bad flags) are InputError: the CLI prints one line
// `hemirad: error: <what>` and exits 2. Everything else exits 1.
#pragma once
#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace hemirad {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class... Args>
[[noreturn]] void fail(fmt::format_string<Args...> format, Args&&... args) {
  throw InputError(fmt::format(format, std::forward<Args>(args)...));
}

constexpr int kExitInputError = 2;
constexpr int kExitFailure = 1;

// Prints `hemirad: warning: <message>` on stderr.
void warn(const std::string& message);

}  // namespace hemirad
