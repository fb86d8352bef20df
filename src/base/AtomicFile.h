// Outputs are written under a temporary name in the same folder and renamed into place, so
// a reader never sees a half-written file and a failure leaves nothing behind. A path that is
// not a regular file (a FIFO, /dev/stdout, a terminal) or is a symlink is written through
// instead: renaming would replace the pipe or the link rather than feed it.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace hemirad {

// Calls write(tmpPath), then renames tmpPath to path. On any exception the temporary file is
// removed and the error rethrown. Throws InputError if the folder is not writable. A symlink
// is followed (the file it names is replaced atomically, the link stays); a path that exists
// and is not a regular file gets the finished temporary file's bytes copied into it.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);
// Writes `text` to `path` atomically ("-": to stdout).
void writeTextFile(const std::string& path, const std::string& text);
// Fails with InputError naming `flag` now, before hours of solving, if `path` cannot be created
// (or, for an existing FIFO or device, cannot be opened for writing). "-" (stdout) passes.
void checkWritable(const std::string& path, const std::string& flag);
// Fails with InputError naming `flag` unless `path` ends in one of `extensions` (".exr", lower
// case; the path's own is compared case-insensitively). "-" passes when `stdoutOk`, and a stream
// (isStream: /dev/stdout, a FIFO) always: it gets the flag's first format.
void checkExtension(const std::string& path, const std::string& flag, const std::vector<std::string>& extensions,
                    bool stdoutOk = false);
// True for an existing path that is not a regular file or folder: a FIFO, a device, a socket.
bool isStream(const std::string& path);

}  // namespace hemirad
