#include "src/scene/SceneFormat.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "src/base/Error.h"

namespace hemirad {

namespace {

// Mesh and scene formats people hand a renderer; anything else is tried as OBJ text.
const std::set<std::string> kOtherFormats = {
    ".3ds",  ".3mf", ".abc", ".ac",  ".amf",  ".ase",  ".blend", ".c4d",  ".dae",  ".dxf", ".fbx",  ".ifc",
    ".iges", ".igs", ".lwo", ".ma",  ".max",  ".mb",   ".md2",   ".md3",  ".ms3d", ".off", ".ply",  ".skp",
    ".step", ".stl", ".stp", ".usd", ".usda", ".usdc", ".usdz",  ".vrml", ".wrl",  ".x3d", ".x3db", ".xaml"};

std::string lowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::string head(const std::string& path, std::size_t bytes) {
  std::ifstream in(path, std::ios::binary);
  std::string out(bytes, '\0');
  in.read(out.data(), std::streamsize(bytes));
  out.resize(std::size_t(in.gcount()));
  return out;
}

// A byte order mark FF FE or FE FF, or (without one) a NUL in every other byte of the start.
bool isUtf16(const std::string& start) {
  if (start.size() >= 2 && ((start[0] == '\xFF' && start[1] == '\xFE') || (start[0] == '\xFE' && start[1] == '\xFF')))
    return true;
  const std::size_t n = std::min<std::size_t>(start.size(), 64) & ~std::size_t(1);
  if (n < 4) return false;
  for (std::size_t first : {0, 1}) {
    bool nulPattern = true;
    for (std::size_t k = 0; k < n && nulPattern; k += 2)
      nulPattern = start[k + first] == '\0' && start[k + 1 - first] != '\0';
    if (nulPattern) return true;
  }
  return false;
}

[[noreturn]] void failGltf1(const std::string& path) {
  fail("{}: glTF 1.0 is not supported; convert it to glTF 2.0 (for example with gltf-pipeline)", path);
}

}  // namespace

SceneFormat sceneFormat(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (kOtherFormats.count(ext))
    fail("{}: unsupported format {}: hemirad reads OBJ (+MTL) and glTF 2.0 (.gltf, .glb)", path, ext);
  if (ext == ".mtl") fail("{}: is a material library (MTL); give the OBJ that names it (mtllib)", path);
  const std::string start = head(path, 64);
  if (ext == ".glb") {
    // The binary header: magic "glTF", then the container version (1: glTF 1.0's KHR_binary_glTF).
    std::uint32_t version = 0;
    if (start.size() >= 8 && start.compare(0, 4, "glTF") == 0)
      std::copy_n(start.data() + 4, 4, reinterpret_cast<char*>(&version));
    if (version == 1) failGltf1(path);
    return SceneFormat::Gltf;
  }
  if (isUtf16(start)) fail("{} is UTF-16 text; save it as UTF-8 or ASCII", path);
  return ext == ".gltf" ? SceneFormat::Gltf : SceneFormat::Obj;
}

void refuseGltf1(const std::string& path, const std::string& assetVersion) {
  if (assetVersion.rfind("1.", 0) == 0) failGltf1(path);
  if (!assetVersion.empty()) return;
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) return;
  if (auto a = j.find("asset"); a != j.end() && a->is_object()) {
    auto v = a->find("version");
    if (v != a->end() && v->is_string() && v->get<std::string>().rfind("1.", 0) == 0) failGltf1(path);
  }
  for (const char* key : {"meshes", "nodes", "accessors"})
    if (auto d = j.find(key); d != j.end() && d->is_object()) failGltf1(path);
}

}  // namespace hemirad
