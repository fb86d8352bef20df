// Where each pixel of a camera image lies relative to the scene's edges, for `hemirad compare`
// (docs/reference.md#regions): the surface seen through each pixel centre, traced on the CPU
// through the BVH (src/solver/Bvh.h) from the scene and camera the images were rendered with,
// so any two images of that view can be compared, whoever rendered them. A surface is an
// object's plane (a tessellated wall is one surface). A pixel's edge distance counts pixels
// (Chebyshev) to the nearest pixel seeing another surface or nothing; its crease distance, to
// the nearest such pixel across a concave crease: two surfaces meeting at an inside edge (the
// room's corners, a block standing on the floor), where radiosity's discretisation errs most.
// Its light distance, for a pixel seeing a surface parallel to an emitter, facing its way and
// within the contact distance of its plane (src/scene/Contacts.h: the ceiling around a flush or
// hung light), counts pixels to the nearest pixel seeing that emitter: the light's rim, where
// elements straddling it (half hidden above a hung light) bleed dark or bright into the ceiling;
// pixels whose square overlaps the light's image are left out (kFar): the light's coverage of
// them is anti-aliasing, whose error swamps the ceiling's.
#pragma once
#include <cstdint>
#include <vector>

#include "src/scene/Camera.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct PixelRegions {
  static constexpr int kEdgeReach = 4;    // edge distances are counted up to here
  static constexpr int kCreaseReach = 3;  // crease distances up to here
  static constexpr int kLightReach = 3;   // light distances up to here
  static constexpr int kFar = 1 << 20;    // beyond the reach
  int width = 0, height = 0;
  std::vector<std::uint32_t> polygon;  // per pixel (rows top-down); kNoPolygon where none is seen
  std::vector<int> edgeDistance, creaseDistance, lightDistance;
};

PixelRegions pixelRegions(const Scene& scene, const Camera& camera, int width, int height);

}  // namespace hemirad
