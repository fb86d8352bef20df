#include "src/base/AtomicFile.h"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "src/base/Error.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {
// Keeps the extension last, so libraries that pick a format by name still see it.
std::string tempName(const std::string& path) {
  fs::path p(path);
  return (p.parent_path() / (p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string())).string();
}
}  // namespace

void checkWritable(const std::string& path, const std::string& flag) {
  fs::path p(path);
  fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail("{} {}: folder '{}' does not exist", flag, path, dir.string());
  if (fs::is_directory(p, ec)) fail("{} {}: is a folder", flag, path);
  if (access(dir.c_str(), W_OK) != 0) fail("{} {}: folder '{}' is not writable", flag, path, dir.string());
}

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  std::string tmp = tempName(path);
  try {
    write(tmp);
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) fail("{}: cannot write: {}", path, ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void writeTextFile(const std::string& path, const std::string& text) {
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << text;
    if (!out.flush()) fail("{}: write failed", path);
  });
}

}  // namespace hemirad
