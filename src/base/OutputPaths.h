// A run's output paths, checked together before any work (docs/solve.md#outputs): nothing the
// user had is overwritten by accident, and no two outputs fight over one file or stream.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

struct OutputPath {
  std::string flag, path;
  std::vector<std::string> extensions;  // ".exr", lower case; empty: any name
  bool stdoutOk = false;                // "-" is stdout
};

// A file the run reads: the scene, its material libraries, buffers and textures, a checkpoint.
struct InputPath {
  std::string what, path;  // "the scene", "s.obj"
};

// Each output's extension and folder (checkExtension, checkWritable); then no two outputs on one
// file or stream after symlinks ("-", /dev/stdout and /dev/fd/1 are one stream; /dev/null takes
// any number), and no output on an input. Fails with one InputError naming both.
void checkOutputs(const std::vector<OutputPath>& outputs, const std::vector<InputPath>& inputs);

// An output folder's default, never an earlier run's: ./NAME, or NAME-2, NAME-3, ..., the first
// that does not exist yet (a default of docs/experiments overwrote a checkout's shipped figures).
std::string freshFolder(const std::string& name);

}  // namespace hemirad
