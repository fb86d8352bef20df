// The scene and its solution as glTF 2.0 (.glb) for engines and viewers: every polygon fanned
// into triangles, one primitive per scene material, TEXCOORD_1 addressing the lightmap
// (src/output/Lightmap.h), which is written beside the .glb as OUT.lightmap.exr (linear B) and
// OUT.lightmap.png (tone mapped as --image, the texture the .glb references). The lightmap is
// each material's emissiveTexture (texCoord 1) over a black base colour: what viewers show
// unlit; extras.hemirad keeps the material's reflectance and emission and the EXR's name.
// docs/gltf.md, "Lightmap export".
#pragma once
#include <string>
#include <vector>

#include "src/output/Lightmap.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct GltfPaths {
  std::string glb, exr, png;
};
// OUT.glb's lightmap files: OUT.lightmap.exr and OUT.lightmap.png.
GltfPaths gltfPaths(const std::string& glb);

// Writes the three files (each atomically; the images first, so the .glb never names a missing
// one). `aspect` is the camera's width / height; `exposureScale` tone-maps the PNG. Returns the
// lightmap it wrote.
Lightmap writeGltf(const GltfPaths& paths, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                   const Camera& camera, double aspect, double exposureScale);

}  // namespace hemirad
