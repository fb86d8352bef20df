#include "src/solver/BvhBuffers.h"

#include "src/solver/ShaderContract.h"

namespace hemirad {

BvhBuffers::BvhBuffers(const Bvh& bvh)
    : nodes_(std::span<const BvhNode>(bvh.nodes())), triangles_(std::span<const BvhTriangle>(bvh.triangles())) {}

void BvhBuffers::bind() const {
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_BVH_NODES);
  triangles_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_BVH_TRIANGLES);
}

}  // namespace hemirad
