// An exported .glb read back with tinygltf as an engine would (tests/LightmapGLTest.cpp): its
// triangles with TEXCOORD_1, its camera, how its materials reference the lightmap; and the
// luminance of edge bands and interiors of a render.
#pragma once
#include <string>
#include <vector>

#include "src/output/Image.h"
#include "src/output/LightmapView.h"
#include "src/scene/Camera.h"

namespace hemirad::test {

struct ReloadedGltf {
  std::vector<LightmapVertex> triangles;  // uv: TEXCOORD_1; surface: the fan (polygon) a triangle belongs to
  Camera camera;
  double aspect = 1;
  std::string imageUri;                // the lightmap texture's image, if external
  std::string embeddedImage;           // its bytes, if in the binary chunk
  int samplerFilter = 0;               // mag filter, if min agrees (else -1)
  int samplerWrap = 0;                 // wrapS, if wrapT agrees (else -1)
  std::vector<int> emissiveTexCoords;  // per material
  std::vector<double> baseColorSums;   // per material: R + G + B of baseColorFactor
};
// Fails the test if tinygltf cannot read `path`.
ReloadedGltf reloadGltf(const std::string& path);

// Mean luminance over the pixels (of `image`) at chessboard distance < band from an edge pixel
// (surface -1, or beside a pixel of another surface), and over the interior: farther than 2
// pixels from any; background (-2) left out.
struct Bands {
  double band1 = 0, band2 = 0, interior = 0;
};
Bands bandLuminance(const Image& image, const std::vector<int>& surface);

}  // namespace hemirad::test
