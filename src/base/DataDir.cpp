#include "src/base/DataDir.h"

#include <filesystem>

namespace hemirad {

namespace fs = std::filesystem;

const std::string& dataDir() {
  static const std::string dir = [] {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    const fs::path installed = exe.parent_path().parent_path() / "share" / "hemirad";
    if (!ec && fs::is_directory(installed, ec)) return installed.string();
    return std::string(HEMIRAD_SOURCE_DIR);
  }();
  return dir;
}

std::string findScene(const std::string& path) {
  std::error_code ec;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path, ec)) return path;
  const fs::path shipped = fs::path(dataDir()) / path;
  return fs::exists(shipped, ec) ? shipped.string() : path;
}

}  // namespace hemirad
