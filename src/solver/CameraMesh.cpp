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
  float normal[3];  // a curved chart's smooth normal, else 0 (the polygon's own)
};
}  // namespace

CameraMesh::CameraMesh(const Scene& scene, const Atlas& atlas)
    : boundsMin_(scene.boundsMin()), boundsMax_(scene.boundsMax()) {
  std::vector<CameraVertex> verts;
  const auto& polys = scene.polygons();
  for (std::uint32_t id = 0; id < polys.size(); ++id) {
    const Poly3& v = polys[id].vertices;
    const bool curved = !atlas.vertexNormals.empty() && !atlas.charts[atlas.chartOf[id]].planar;
    auto vertex = [&](std::size_t k) {
      const glm::dvec3& p = v[k];
      const glm::dvec2 a = atlas.atlasCoord(int(id), p);
      const glm::vec3 n = curved ? glm::vec3(atlas.vertexNormals[id][k]) : glm::vec3(0.0f);
      verts.push_back({{float(p.x), float(p.y), float(p.z)}, {float(a.x), float(a.y)}, id, {n.x, n.y, n.z}});
    };
    for (size_t k = 1; k + 1 < v.size(); ++k) vertex(0), vertex(k), vertex(k + 1);
  }
  vertexCount_ = verts.size();
  vertices_ = gl::Buffer(std::span<const CameraVertex>(verts));
  vao_.vertexBuffer(vertices_, sizeof(CameraVertex));
  vao_.floatAttribute(0, 3, offsetof(CameraVertex, position));
  vao_.floatAttribute(1, 2, offsetof(CameraVertex, atlas));
  vao_.uintAttribute(2, offsetof(CameraVertex, polygon));
  vao_.floatAttribute(3, 3, offsetof(CameraVertex, normal));
}

void CameraMesh::draw() const {
  vao_.bind();
  gl::drawTriangles(vertexCount_);
}

glm::mat4 CameraMesh::viewProjection(const Camera& camera, double aspect) const {
  return camera.viewProjection(aspect, nearPlane(camera, boundsMin_, boundsMax_));
}

}  // namespace hemirad
