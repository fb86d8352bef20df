// The scene loader's fuzz input and the one code path that loads it, shared by the libFuzzer
// target (FuzzSceneLoader.cpp) and the regression test (tests/FuzzRegressionTest.cpp), so a
// stored crasher replays exactly as the fuzzer ran it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hemirad::fuzz {

// An input is OBJ text, this separator line, then MTL text (no separator: all OBJ, empty MTL).
// ci/fuzz writes the seeds in this form.
inline constexpr std::string_view kMtlSeparator = "\n@mtl\n";
// An input starting with this line is instead a glTF file (JSON, buffers as data URIs).
inline constexpr std::string_view kGltfPrefix = "@gltf\n";

struct Outcome {
  bool loaded = false;       // loaded, atlas built, solvable
  std::string error;         // otherwise the InputError's message
  std::size_t elements = 0;  // atlas elements when loaded
};

// Writes `mtllib scene.mtl` + the OBJ part to scene.obj and the MTL part to scene.mtl in this
// process's temp folder (/dev/shm, else $TMPDIR) (a glTF input: the rest to scene.gltf), then runs loadScene, an atlas
// of about 200 elements (as `hemirad info` does) and validateSolvable. An InputError is the expected refusal and is
// returned; any other exception propagates (a bug).
Outcome loadFuzzInput(std::string_view input);

}  // namespace hemirad::fuzz
