#include "src/output/DirectLight.h"

#include <span>

#include "gl/Backend.h"

#include "src/solver/Bvh.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

std::vector<glm::vec4> emitterPieces(const Scene& scene) {
  std::vector<glm::vec4> slots;
  for (std::uint32_t id = 0; id < scene.polygons().size(); ++id) {
    const ScenePolygon& p = scene.polygons()[id];
    if (!scene.materials[p.material].emissive()) continue;
    for (std::size_t k = 1; k + 1 < p.vertices.size(); k += 2) {
      const std::size_t count = std::min<std::size_t>(3, p.vertices.size() - k);  // 2 or 3 after v0
      const std::size_t base = slots.size();
      slots.resize(base + kShapeStride, glm::vec4(0));
      slots[base] = glm::vec4(float(count + 1), uintBitsToFloat(1), 0, uintBitsToFloat(id));
      slots[base + 1] = glm::vec4(glm::vec3(p.vertices[0]), 1);
      for (std::size_t i = 0; i < count; ++i) slots[base + 2 + i] = glm::vec4(glm::vec3(p.vertices[k + i]), 1);
    }
  }
  return slots;
}

DirectLight::DirectLight(const Scene& scene, double farDistance, int grid)
    : grid_(grid), segmentEps_(float(kSegmentTolerance * farDistance)) {  // the gather's tolerance
  const std::vector<glm::vec4> pieces = emitterPieces(scene);
  pieceCount_ = unsigned(pieces.size() / kShapeStride);
  if (!pieces.empty()) pieces_ = gl::Buffer(std::span<const glm::vec4>(pieces));
  bvh_ = BvhBuffers(Bvh(scene));
}

void DirectLight::bind(const gl::Program& program) const {
  if (pieceCount_) pieces_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOOTER_SHAPES);
  bvh_.bind();
  program.set("emitterBase", 0u);
  program.set("directGrid", grid_);
  program.set("segmentEps", segmentEps_);
  program.set("pyramidTurns", gl::softwareRenderer() ? kSoftwarePyramidTurns : ~0u);
  bindStrips(program, 0, strips());
}

void DirectLight::bindStrips(const gl::Program& program, unsigned first, unsigned end) const {
  program.set("stripFirst", first);
  program.set("stripEnd", end);
}

}  // namespace hemirad
