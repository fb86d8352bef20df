#include "src/base/OutputPaths.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <optional>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {

bool isDevNull(const struct stat& st) {
  struct stat null {};
  return S_ISCHR(st.st_mode) && ::stat("/dev/null", &null) == 0 && st.st_rdev == null.st_rdev;
}

// What a path names once written: the device and inode of an existing file or stream (so a
// symlink, /dev/stdout and "-" meet what they point at), else the path with its folders' links
// resolved. None for /dev/null, which any number of outputs may share.
std::optional<std::string> identity(const std::string& path) {
  struct stat st {};
  const bool exists = path == "-" ? ::fstat(STDOUT_FILENO, &st) == 0 : ::stat(path.c_str(), &st) == 0;
  if (exists) {
    if (isDevNull(st)) return std::nullopt;
    return "inode " + std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  }
  if (path == "-") return "stdout";
  std::error_code ec;
  return "path " + fs::weakly_canonical(followLinks(fs::absolute(path, ec)), ec).string();  // a dangling link too
}

}  // namespace

void checkOutputs(const std::vector<OutputPath>& outputs, const std::vector<InputPath>& inputs) {
  for (const OutputPath& o : outputs) {
    if (!o.extensions.empty()) checkExtension(o.path, o.flag, o.extensions, o.stdoutOk);
    checkWritable(o.path, o.flag);
  }
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::optional<std::string> mine = identity(outputs[i].path);
    if (!mine) continue;
    for (const InputPath& in : inputs)
      if (identity(in.path) == mine)
        fail("{} {}: is {} ({}); hemirad never writes over what it reads", outputs[i].flag, outputs[i].path, in.what,
             in.path);
    for (std::size_t j = 0; j < i; ++j)
      if (identity(outputs[j].path) == mine)
        fail("{} {} and {} {} are the same {}; give each output its own", outputs[j].flag, outputs[j].path,
             outputs[i].flag, outputs[i].path, isStream(outputs[i].path) || outputs[i].path == "-" ? "stream" : "file");
  }
}

std::string freshFolder(const std::string& name) {
  std::error_code ec;
  std::string path = name;
  for (int k = 2; fs::exists(fs::symlink_status(path, ec)); ++k) path = name + "-" + std::to_string(k);
  return path;
}

}  // namespace hemirad
