#include "src/solver/BvhBuffers.h"

#include <cstdint>
#include <stdexcept>

#include <fmt/format.h>

#include "gl/State.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

BvhBuffers::BvhBuffers(const Bvh& bvh)
    : nodes_(std::span<const BvhNode>(bvh.nodes())),
      triangles_(std::span<const BvhTriangle>(bvh.triangles())),
      walksCut_(std::span<const std::uint32_t>(std::vector<std::uint32_t>{0})) {}

void BvhBuffers::bind() const {
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_BVH_NODES);
  triangles_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_BVH_TRIANGLES);
  walksCut_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_WALKS_CUT);
}

bool BvhBuffers::walksCut() const {
  std::uint32_t cut = 0;
  gl::barrier(gl::Barrier::BufferUpdate);
  walksCut_.read(0, sizeof cut, &cut);
  return cut != 0;
}

void BvhBuffers::clearWalksCut() const { walksCut_.clear(0u); }

void BvhBuffers::requireWholeWalks(std::string_view what) const {
  if (walksCut())
    throw std::runtime_error(fmt::format(
        "{}: the software renderer ended a BVH walk early (llvmpipe stops all of a shader invocation's loops "
        "after 65,535 turns in all), so the result would be wrong; run it on a GPU (--backend egl) or with "
        "fewer elements, near shooters or samples",
        what));
}

}  // namespace hemirad
