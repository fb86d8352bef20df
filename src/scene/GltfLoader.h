// glTF 2.0 scenes (.gltf, .glb) through tinygltf into the same Scene as OBJ+MTL: every mesh
// primitive of the default scene's nodes, placed by the node transforms; baseColorFactor is the
// reflectance rho, emissiveFactor x KHR_materials_emissive_strength the emitted radiosity E; the
// first perspective camera becomes the scene's camera. Triangle strips and fans (modes 5, 6) are
// read as triangles; points and lines are skipped with a warning. Triangle fans that form one
// planar convex polygon (how exporters, and scenes/tools/obj_to_gltf.py, write quads and n-gons)
// are joined back into it, so a glTF scene has the charts its OBJ twin has.
#pragma once
#include <string>

#include "src/scene/Scene.h"

namespace hemirad {

bool isGltfPath(const std::string& path);  // .gltf or .glb, any case
// Throws InputError ("FILE: what", one line) for what cannot be used, like loadScene for OBJ.
Scene loadGltf(const std::string& path);

}  // namespace hemirad
