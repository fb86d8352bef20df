#include "src/base/AtomicFile.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "src/base/Error.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {
// Keeps the extension last, so libraries that pick a format by name still see it.
std::string tempName(const fs::path& p, const fs::path& dir) {
  return (dir / (p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string())).string();
}

// Every byte to `fd`, each write checked (a full disk: ENOSPC); `path` names the file in errors.
void writeAll(int fd, std::string_view bytes, const std::string& path) {
  while (!bytes.empty()) {
    const ssize_t k = ::write(fd, bytes.data(), bytes.size());
    if (k < 0 && errno == EINTR) continue;
    if (k < 0) fail("{}: cannot write: {}", path, std::strerror(errno));
    bytes.remove_prefix(std::size_t(k));
  }
}

// Writes, closes and (for a regular file) fsyncs `fd`, each step checked; closes it on failure too.
void finish(int fd, std::string_view bytes, const std::string& path, bool sync) {
  try {
    writeAll(fd, bytes, path);
    if (sync && ::fsync(fd) != 0) fail("{}: cannot write: {}", path, std::strerror(errno));
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail("{}: cannot write: {}", path, std::strerror(errno));
}

// A new regular file `file` holding `bytes`; `path` is the name the user gave.
void writeNewFile(const std::string& file, std::string_view bytes, const std::string& path) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("{}: cannot write: {}", path, std::strerror(errno));
  finish(fd, bytes, path, true);
}

// A stream (FIFO, device, /dev/stdout) gets the bytes appended: /dev/stdout redirected to a
// file (`>>`) must not be truncated; a pipe ignores it.
void feedStream(const std::string& path, std::string_view bytes) {
  std::fflush(stdout);  // what stdio holds for stdout goes first
  if (path == "-") return writeAll(STDOUT_FILENO, bytes, "stdout");
  const int fd = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd < 0) fail("{}: cannot write: {}", path, std::strerror(errno));
  finish(fd, bytes, path, false);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("{}: cannot read back", path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A stream is fed from a finished temporary file in the temp folder, since writers such as
// OpenEXR seek and a pipe cannot.
void writeThrough(const std::string& path, const std::function<void(const std::string&)>& write) {
  std::error_code ec;
  fs::path dir = fs::temp_directory_path(ec);
  if (ec) dir = "/tmp";
  const std::string tmp = tempName(fs::path(path).filename().empty() ? fs::path("out") : fs::path(path), dir);
  try {
    write(tmp);
    feedStream(path, readFile(tmp));
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::remove(tmp, ec);
}
}  // namespace

fs::path followLinks(fs::path p) {
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

void writeFileBytes(const std::string& path, std::string_view bytes) {
  OutputBatch batch;
  batch.add("", path, bytes);
  batch.commit();
}

void writeTextFile(const std::string& path, const std::string& text) { writeFileBytes(path, text); }

namespace {
// "--image out.png: cannot write: No space left on device": the flag first, when there is one.
[[noreturn]] void rethrowNaming(const std::string& flag, const InputError& e) {
  if (flag.empty()) throw e;
  throw InputError(flag + " " + e.what());
}
}  // namespace

void OutputBatch::add(const std::string& flag, const std::string& path, std::string_view bytes) {
  if (path == "-" || isStream(path)) {
    staged_.push_back({flag, path, "", std::string(bytes)});
    return;
  }
  const fs::path target = followLinks(path);  // a symlink stays; the file it names is replaced
  staged_.push_back({flag, path, tempName(target, target.parent_path()), ""});
  try {
    writeNewFile(staged_.back().tmp, bytes, path);
  } catch (const InputError& e) {
    rethrowNaming(flag, e);  // the destructor removes the partial temporary file with the others
  }
}

void OutputBatch::commit() {
  // Streams first: they cannot be taken back, while a staged file not yet renamed still can.
  for (bool streams : {true, false})
    for (Staged& s : staged_) {
      if (s.tmp.empty() != streams) continue;
      try {
        if (streams) {
          feedStream(s.path, s.bytes);
          continue;
        }
        std::error_code ec;
        fs::rename(s.tmp, followLinks(s.path), ec);
        if (ec) fail("{}: cannot write: {}", s.path, ec.message());
        s.tmp.clear();
      } catch (const InputError& e) {
        rethrowNaming(s.flag, e);
      }
    }
  staged_.clear();
}

OutputBatch::~OutputBatch() {
  for (const Staged& s : staged_) {
    std::error_code ignored;
    if (!s.tmp.empty()) fs::remove(s.tmp, ignored);
  }
}

}  // namespace hemirad
