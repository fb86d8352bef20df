#include "tests/fuzz/FuzzInput.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "src/base/Error.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"

namespace hemirad::fuzz {

namespace {

namespace fs = std::filesystem;

// Bounds the atlas (the loader does not) so a valid but huge scene is a refusal, not an OOM.
constexpr std::size_t kElements = 200;
constexpr int kMaxAtlasSize = 2048;

// One folder per process, removed at exit; /dev/shm keeps the fuzzer's writes off the disk.
struct TempFolder {
  fs::path dir;
  TempFolder() {
    std::error_code ec;
    fs::path base = fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK) == 0 ? fs::path("/dev/shm")
                                                                                      : fs::temp_directory_path();
    dir = base / ("hemirad-fuzz-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

void writeFile(const fs::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), std::streamsize(text.size()));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

// The OBJ part (after an mtllib line) and the MTL part of an OBJ+MTL input.
void writeObjAndMtl(const fs::path& dir, std::string_view input) {
  size_t cut = input.find(kMtlSeparator);
  std::string_view obj = input.substr(0, cut);
  std::string_view mtl = cut == std::string_view::npos ? std::string_view() : input.substr(cut + kMtlSeparator.size());
  writeFile(dir / "scene.mtl", mtl);
  writeFile(dir / "scene.obj", "mtllib scene.mtl\n" + std::string(obj));
}

}  // namespace

Outcome loadFuzzInput(std::string_view input) {
  static TempFolder folder;
  fs::path scenePath = folder.dir / "scene.obj";
  if (input.substr(0, kGltfPrefix.size()) == kGltfPrefix) {
    scenePath = folder.dir / "scene.gltf";
    writeFile(scenePath, input.substr(kGltfPrefix.size()));
  } else {
    writeObjAndMtl(folder.dir, input);
  }

  Outcome out;
  try {
    Scene scene = loadScene(scenePath.string());
    Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, kElements), kMaxAtlasSize);
    validateSolvable(scene);
    out.loaded = true;
    out.elements = atlas.elements;
  } catch (const InputError& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace hemirad::fuzz
