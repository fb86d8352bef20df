// A lightmapped mesh drawn as an engine draws it: triangles with the lightmap's UVs, the
// lightmap an RGBA32F texture sampled with GL_LINEAR. Checks that an exported lightmap
// (src/output/GltfWriter.h) shows what hemirad's own render shows (tests/LightmapGLTest.cpp).
#pragma once
#include <cstdint>
#include <vector>

#include "src/output/Image.h"
#include "src/scene/Camera.h"

namespace hemirad {

struct LightmapVertex {
  float position[3];
  float uv[2];            // lightmap coordinates (glTF's TEXCOORD_1: v runs down the image)
  std::uint32_t surface;  // which planar surface the triangle lies on
};

struct LightmapRender {
  Image image;               // linear RGB, rows top to bottom
  std::vector<int> surface;  // per pixel: the surface all its samples show; -1 where they differ (edges), -2 none
};

// Draws `triangles` (3 vertices each) from `camera` at width x height, `supersample` x that
// boxed down as Renderer does; `lightmap` is linear RGB with row 0 at v = 0.
LightmapRender renderLightmapped(const std::vector<LightmapVertex>& triangles, const Image& lightmap,
                                 const Camera& camera, int width, int height, int supersample = 2);

}  // namespace hemirad
