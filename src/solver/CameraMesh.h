// The scene's polygons as triangles with their atlas coordinates and polygon ids, in a static
// vertex buffer: what every view from a camera draws (the renderer, the importance view).
#pragma once
#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"

namespace hemirad {

class CameraMesh {
 public:
  CameraMesh(const Scene& scene, const Atlas& atlas);
  // Binds the vertex array and draws every triangle (attributes 0 position, 1 atlas, 2 polygon,
  // 3 the smooth normal on a curved chart, else 0).
  void draw() const;
  // A camera's reversed-Z view-projection (gl/State.h, DepthRange::Reversed) whose near plane lies in front
  // of the whole scene: half the eye's distance to the scene's bounds, or a millionth of the
  // scene's size when the eye is inside them.
  glm::mat4 viewProjection(const Camera& camera, double aspect) const;

 private:
  gl::Buffer vertices_;
  gl::VertexArray vao_;
  std::size_t vertexCount_ = 0;
  glm::dvec3 boundsMin_, boundsMax_;
};

}  // namespace hemirad
