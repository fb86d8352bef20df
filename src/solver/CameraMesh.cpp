#include "src/solver/CameraMesh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gl/State.h"

namespace hemirad {

namespace {
struct CameraVertex {
  float position[3];
  float atlas[2];
  std::uint32_t polygon;
};
}  // namespace

CameraMesh::CameraMesh(const Scene& scene, const Atlas& atlas)
    : boundsMin_(scene.boundsMin()), boundsMax_(scene.boundsMax()) {
  std::vector<CameraVertex> verts;
  const auto& polys = scene.polygons();
  for (std::uint32_t id = 0; id < polys.size(); ++id) {
    const Poly3& v = polys[id].vertices;
    auto vertex = [&](const glm::dvec3& p) {
      glm::dvec2 a = atlas.atlasCoord(int(id), p);
      verts.push_back({{float(p.x), float(p.y), float(p.z)}, {float(a.x), float(a.y)}, id});
    };
    for (size_t k = 1; k + 1 < v.size(); ++k) vertex(v[0]), vertex(v[k]), vertex(v[k + 1]);
  }
  vertexCount_ = verts.size();
  vertices_ = gl::Buffer(std::span<const CameraVertex>(verts));
  vao_.vertexBuffer(vertices_, sizeof(CameraVertex));
  vao_.floatAttribute(0, 3, offsetof(CameraVertex, position));
  vao_.floatAttribute(1, 2, offsetof(CameraVertex, atlas));
  vao_.uintAttribute(2, offsetof(CameraVertex, polygon));
}

void CameraMesh::draw() const {
  vao_.bind();
  gl::drawTriangles(vertexCount_);
}

glm::mat4 CameraMesh::viewProjection(const Camera& camera, double aspect) const {
  return camera.viewProjection(aspect, nearPlane(camera, boundsMin_, boundsMax_));
}

}  // namespace hemirad
