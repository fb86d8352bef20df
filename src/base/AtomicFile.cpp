#include "src/base/AtomicFile.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "src/base/Error.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {
// Keeps the extension last, so libraries that pick a format by name still see it.
std::string tempName(const fs::path& p, const fs::path& dir) {
  return (dir / (p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string())).string();
}

// A stream (FIFO, device) is fed from a finished temporary file in the temp folder, since
// writers such as OpenEXR seek and a pipe cannot.
void writeThrough(const std::string& path, const std::function<void(const std::string&)>& write) {
  std::error_code ec;
  fs::path dir = fs::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  const std::string tmp = tempName(fs::path(path).filename().empty() ? fs::path("out") : fs::path(path), dir);
  try {
    write(tmp);
    std::ifstream in(tmp, std::ios::binary);
    // Appends: /dev/stdout redirected to a file (`>>`) must not be truncated; a pipe ignores it.
    std::ofstream out(path, std::ios::binary | std::ios::app);
    if (!in || !out) fail("{}: cannot write", path);
    out << in.rdbuf();
    if (!out.flush()) fail("{}: write failed", path);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::remove(tmp, ec);
}
}  // namespace

// The file a chain of symlinks names, even when it does not exist yet (a dangling link).
static fs::path followLinks(fs::path p) {
  std::error_code ec;
  for (int hop = 0; hop < 40 && fs::is_symlink(fs::symlink_status(p, ec)); ++hop) {
    fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return p.lexically_normal();
}

bool isStream(const std::string& path) {
  std::error_code ec;
  fs::file_status s = fs::status(path, ec);
  if (ec || !fs::exists(s) || fs::is_directory(s)) return false;
  if (!fs::is_regular_file(s)) return true;
  // /dev/stdout redirected to a file names it through /proc/self/fd: the shell holds it open.
  const std::string real = fs::canonical(path, ec).string();
  const std::string given = fs::absolute(path, ec).string();
  auto special = [](const std::string& p) { return p.rfind("/dev/", 0) == 0 || p.rfind("/proc/", 0) == 0; };
  return special(given) || special(real);
}

void checkWritable(const std::string& path, const std::string& flag) {
  if (path == "-") return;
  fs::path p(path);
  std::error_code ec;
  if (isStream(path)) {
    if (access(path.c_str(), W_OK) != 0) fail("{} {}: is not writable", flag, path);
    return;
  }
  p = followLinks(p);  // a symlink: the file it names
  fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  if (!fs::is_directory(dir, ec)) fail("{} {}: folder '{}' does not exist", flag, path, dir.string());
  if (fs::is_directory(p, ec)) fail("{} {}: is a folder", flag, path);
  if (access(dir.c_str(), W_OK) != 0) fail("{} {}: folder '{}' is not writable", flag, path, dir.string());
}

void checkExtension(const std::string& path, const std::string& flag, const std::vector<std::string>& extensions,
                    bool stdoutOk) {
  if (path == "-" && stdoutOk) return;
  if (isStream(path)) return;  // /dev/stdout, a FIFO: named by the user, written in the flag's first format
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) return;
  fail("{} {}: {}; the file name must end in {}{}", flag, path,
       ext.empty() ? std::string("no file extension") : fmt::format("'{}' is not a format it writes", ext),
       fmt::join(extensions, " or "), stdoutOk ? " (or be - for stdout)" : "");
}

void writeAtomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  if (isStream(path)) return writeThrough(path, write);
  std::error_code ec;
  const fs::path target = followLinks(path);  // a symlink stays; the file it names is replaced
  std::string tmp = tempName(target, target.parent_path());
  try {
    write(tmp);
    fs::rename(tmp, target, ec);
    if (ec) fail("{}: cannot write: {}", path, ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

void writeTextFile(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::fwrite(text.data(), 1, text.size(), stdout);
    if (std::fflush(stdout) != 0) fail("stdout: write failed");
    return;
  }
  writeAtomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp);
    out << text;
    if (!out.flush()) fail("{}: write failed", path);
  });
}

}  // namespace hemirad
