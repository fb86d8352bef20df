// Outputs are written under a temporary name in the same folder and renamed into place, so
// a reader never sees a half-written file and a failure leaves nothing behind.
#pragma once
#include <functional>
#include <string>

namespace hemirad {

// Calls write(tmpPath), then renames tmpPath to path. On any exception the temporary file is
// removed and the error rethrown. Throws InputError if the folder is not writable.
void writeAtomically(const std::string& path, const std::function<void(const std::string& tmpPath)>& write);
// Writes `text` to `path` atomically.
void writeTextFile(const std::string& path, const std::string& text);
// Fails with InputError naming `flag` now, before hours of solving, if `path` cannot be created.
void checkWritable(const std::string& path, const std::string& flag);

}  // namespace hemirad
