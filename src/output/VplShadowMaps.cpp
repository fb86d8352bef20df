#include "src/output/VplShadowMaps.h"

#include <algorithm>
#include <cstddef>

#include "gl/State.h"
#include "src/scene/ItemMesh.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

VplShadowMaps::VplShadowMaps(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings)
    : tracer_(tracer),
      vpls_(settings.vpls),
      size_(settings.shadowResolution),
      program_(renderProgram("vpl_shadow.vert", "vpl_shadow.frag")),
      depth_(GL_DEPTH_COMPONENT32F, size_, size_, kBatch) {
  const IndexedItemMesh item = indexItemMesh(buildItemMesh(scene, settings.itemSubdivision));
  indexCount_ = item.indices.size();
  vertices_ = gl::Buffer(std::span<const ItemVertex>(item.vertices));
  indices_ = gl::Buffer(std::span<const std::uint32_t>(item.indices));
  vao_.vertexBuffer(vertices_, sizeof(ItemVertex));
  vao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  vao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  vao_.indexBuffer(indices_);
  // Every batch has kBatch layers (a layered framebuffer's attachments match), the last part-used.
  for (unsigned first = 0; first < vpls_; first += kBatch) {
    ids_.emplace_back(GL_R32UI, size_, size_, kBatch);
    targets_.emplace_back();
    targets_.back().attach(GL_COLOR_ATTACHMENT0, ids_.back());
    targets_.back().attach(GL_DEPTH_ATTACHMENT, depth_);
    targets_.back().checkComplete("VPL shadow maps");
  }
  program_.set("farDistance", float(2.0 * tracer.sceneDiagonal() + 1e-6));
  program_.set("faceSize", float(size_));
}

void VplShadowMaps::render() {
  gl::RasterState{.width = size_, .height = size_, .clipDistance0 = true}.apply();
  tracer_.bind();
  program_.use();
  vao_.bind();
  for (unsigned b = 0; b < batches(); ++b) {
    const unsigned first = b * kBatch, count = std::min<unsigned>(kBatch, vpls_ - first);
    program_.set("vplFirst", first);
    targets_[b].clearColor(0xFFFFFFFFu);
    targets_[b].clearDepth(1.0f);
    targets_[b].bind();
    gl::drawIndexedTriangles(indexCount_, int(count));
  }
  gl::barrier(gl::Barrier::TextureFetch);
  rendered_ = true;
}

void VplShadowMaps::bind(unsigned batch, unsigned unit) const { ids_[batch].bindUnit(unit); }

}  // namespace hemirad
