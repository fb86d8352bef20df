// Outputs are written under a temporary name in the same folder and renamed into place, so
// a reader never sees a half-written file and a failure leaves nothing behind. A path that is
// not a regular file (a FIFO, /dev/stdout, a terminal) or is a symlink is written through
// instead: renaming would replace the pipe or the link rather than feed it. Every write, fsync
// and close is checked: a full disk is an error naming the path and the reason, never a
// truncated file.
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hemirad {

// Calls write(tmpPath), then renames tmpPath to path. On any exception the temporary file is
// removed and the error rethrown. Throws InputError if the folder is not writable. A symlink
// is followed (the file it names is replaced atomically, the link stays); a path that exists
// and is not a regular file gets the finished temporary file's bytes copied into it.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);
// Writes `bytes` to `path` atomically (a stream, or "-" for stdout: through), every write, fsync
// and close checked.
void writeFileBytes(const std::string& path, std::string_view bytes);
// Writes `text` to `path` atomically ("-": to stdout).
void writeTextFile(const std::string& path, const std::string& text);

// One run's outputs, written all or none. add() stages each file under a temporary name beside
// its target (write, fsync, close, each checked); commit() feeds the streams and renames the
// files into place. Destroyed before commit(), it removes what it staged: a run that fails on
// its third output (a full disk) leaves neither the first two nor a partial third. Errors name
// the flag, the path and the reason.
class OutputBatch {
 public:
  OutputBatch() = default;
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;
  ~OutputBatch();
  void add(const std::string& flag, const std::string& path, std::string_view bytes);
  void commit();

 private:
  struct Staged {
    std::string flag, path, tmp;  // tmp empty: a stream, fed from `bytes` at commit
    std::string bytes;
  };
  std::vector<Staged> staged_;
};

// Fails with InputError naming `flag` now, before hours of solving, if `path` cannot be created
// (or, for an existing FIFO or device, cannot be opened for writing). "-" (stdout) passes.
void checkWritable(const std::string& path, const std::string& flag);
// Fails with InputError naming `flag` unless `path` ends in one of `extensions` (".exr", lower
// case; the path's own is compared case-insensitively). "-" passes when `stdoutOk`, and a stream
// (isStream: /dev/stdout, a FIFO) always: it gets the flag's first format.
void checkExtension(const std::string& path, const std::string& flag, const std::vector<std::string>& extensions,
                    bool stdoutOk = false);
// The file a chain of symlinks names, even when it does not exist yet (a dangling link).
std::filesystem::path followLinks(std::filesystem::path p);
// True for an existing path that is not a regular file or folder: a FIFO, a device, a socket.
bool isStream(const std::string& path);

}  // namespace hemirad
