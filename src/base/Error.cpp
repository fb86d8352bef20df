#include "src/base/Error.h"

#include <cstdio>

namespace hemirad {
void warn(const std::string& message) { std::fprintf(stderr, "hemirad: warning: %s\n", message.c_str()); }
}  // namespace hemirad
