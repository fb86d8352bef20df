// The scene and its solution as glTF 2.0 (.glb) for engines and viewers: every polygon fanned
// into triangles, one primitive per scene material, TEXCOORD_1 addressing the lightmap
// (src/output/Lightmap.h). The lightmap, tone mapped as --image, is a PNG inside the .glb's
// binary chunk (a .glb copied alone still shows its light); its linear B is OUT.lightmap.exr
// beside it (none beside a stream such as /dev/stdout). One mesh and node per scene object. The
// lightmap is each material's emissiveTexture (texCoord 1) over its albedo as base colour: what
// viewers without lights show; extras.hemirad keeps the material's reflectance and emission
// (read back by the glTF loader) and the EXR's name.
// docs/gltf.md, "Lightmap export".
#pragma once
#include <string>
#include <vector>

#include "src/base/AtomicFile.h"
#include "src/output/Lightmap.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct GltfPaths {
  std::string glb, exr;  // exr empty: glb is a stream, written alone
};
// OUT.glb and its linear lightmap OUT.lightmap.exr.
GltfPaths gltfPaths(const std::string& glb);

struct GltfFiles {
  Lightmap map;
  std::string glb, exr;  // the files' bytes
};
// Both files encoded in memory. `aspect` is the camera's width / height; `exposureScale` tone-maps
// the embedded PNG; `lightmap`: its layout (tests compare gutters with the default's clamp).
GltfFiles encodeGltf(const GltfPaths& paths, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                     const Camera& camera, double aspect, double exposureScale, const LightmapOptions& lightmap = {});
// Stages both into a run's outputs, under --gltf.
void stageGltf(OutputBatch& batch, const GltfPaths& paths, const GltfFiles& files);
// Encodes and writes both, all or none. Returns the lightmap it wrote.
Lightmap writeGltf(const GltfPaths& paths, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                   const Camera& camera, double aspect, double exposureScale, const LightmapOptions& lightmap = {});

}  // namespace hemirad
