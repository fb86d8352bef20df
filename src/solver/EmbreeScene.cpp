#include "src/solver/EmbreeScene.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

namespace hemirad {

EmbreeScene::EmbreeScene(const std::vector<glm::vec3>& corners, RTCSceneFlags flags,
                         RTCFilterFunctionN occludedFilter) {
  device_ = rtcNewDevice(nullptr);
  if (!device_) throw std::runtime_error(fmt::format("Embree: no device (error {})", int(rtcGetDeviceError(nullptr))));
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, flags);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  const std::size_t triangles = corners.size() / 3;
  RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<glm::vec3*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(glm::vec3), corners.size()));
  std::copy(corners.begin(), corners.end(), v);
  auto* index = static_cast<std::uint32_t*>(
      rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), triangles));
  for (std::uint32_t i = 0; i < 3 * triangles; ++i) index[i] = i;
  if (occludedFilter) rtcSetGeometryOccludedFilterFunction(g, occludedFilter);
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene_, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(scene_);
}

EmbreeScene::~EmbreeScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

}  // namespace hemirad
