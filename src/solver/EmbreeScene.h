// An Embree device and a scene of one triangle geometry, released together: what the host's ray
// queries share (--visibility bvh traced on a CPU device, src/solver/HostTrace.h; buried texels,
// src/output/BuriedTexels.h). Triangle i is primitive i.
#pragma once
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

namespace hemirad {

class EmbreeScene {
 public:
  // `corners`: three a triangle. `occludedFilter` (may be null): the geometry's rtcOccluded1 filter.
  EmbreeScene(const std::vector<glm::vec3>& corners, RTCSceneFlags flags, RTCFilterFunctionN occludedFilter = nullptr);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene get() const { return scene_; }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace hemirad
