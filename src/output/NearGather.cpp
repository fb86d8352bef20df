#include "src/output/NearGather.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "gl/Limits.h"
#include "src/output/DirectLight.h"
#include "src/output/GatherSources.h"
#include "src/solver/ShaderContract.h"
#include "src/solver/ShooterTree.h"
#include "src/solver/SolverState.h"

namespace hemirad {

namespace {

constexpr int kGatherLevel = 4;  // 16 x 16-texel roots, four levels down to single elements

}  // namespace

std::vector<glm::vec4> sentOn(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B) {
  std::vector<glm::vec4> out(B);
  for (std::size_t t = 0; t < out.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon)
      out[t] -= glm::vec4(glm::vec3(scene.materials[scene.polygons()[atlas.polygonOf[t]].material].emission), 0.0f);
  return out;
}

NearGather::NearGather(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& sent) {
  const ShooterTree tree = buildShooterTree(atlas, atlas.shooterBlocks(kGatherLevel), kGatherLevel);
  blocks_ = unsigned(tree.blocks);
  std::vector<glm::ivec4> rects;
  for (const ShooterNode& n : tree.nodes) rects.push_back(n.rect);
  std::vector<glm::vec4> shapes = shapeTable(scene, atlas, rects).slots;
  emitterBase_ = unsigned((shapes.size() + kShapeStride - 1) / kShapeStride);  // after the last node piece
  shapes.resize(std::size_t(emitterBase_) * kShapeStride, glm::vec4(0.0f));    // pieces start on a slot
  const std::vector<glm::vec4> pieces = emitterPieces(scene);
  shapes.insert(shapes.end(), pieces.begin(), pieces.end());
  gl::requireStorageBlock(shapes.size() * sizeof(glm::vec4),
                          fmt::format("the shapes of {} final-gather nodes", tree.nodes.size()));
  nodes_ = gl::Buffer(std::span<const ShooterNode>(tree.nodes));
  shapes_ = gl::Buffer(std::span<const glm::vec4>(shapes));
  sources_ = gl::Buffer(std::span<const glm::vec4>(gatherSources(atlas, tree.nodes, sent)));
}

void NearGather::bind(const gl::Program& program) const {
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODES);
  sources_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODE_STATS);
  shapes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOOTER_SHAPES);
  program.set("emitterBase", emitterBase_);
  program.set("gatherReach", float(kGatherReach));
  bindBlocks(program, 0, blocks_);
}

void NearGather::bindBlocks(const gl::Program& program, unsigned first, unsigned end) const {
  program.set("gatherFirst", first);
  program.set("gatherEnd", end);
}

}  // namespace hemirad
