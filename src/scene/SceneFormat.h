// Which reader a scene file goes to, and one clear error line for what hemirad cannot read
// (docs/errors.md) instead of a parser's complaint or "no faces": another 3D format (by its
// extension), an MTL given as the scene, UTF-16 text, glTF 1.0.
#pragma once
#include <string>

namespace hemirad {

enum class SceneFormat { Obj, Gltf };

// .gltf and .glb are glTF, .obj and any extension not known as another format are OBJ. Throws
// InputError for another 3D format, an MTL, UTF-16 text, or a glTF 1.0 binary (.glb version 1).
SceneFormat sceneFormat(const std::string& path);

// A .gltf that tinygltf could not read, or read with asset.version `assetVersion`: is it glTF 1.0
// (version 1.x, or its meshes and nodes in dictionaries rather than arrays)? Throws InputError
// naming glTF 1.0 if so.
void refuseGltf1(const std::string& path, const std::string& assetVersion);

}  // namespace hemirad
