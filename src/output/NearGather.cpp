#include "src/output/NearGather.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "gl/Limits.h"
#include "src/output/DirectLight.h"
#include "src/solver/ShaderContract.h"
#include "src/solver/ShooterTree.h"
#include "src/solver/SolverState.h"
#include "src/solver/Subdivide.h"

namespace hemirad {

namespace {

constexpr int kGatherLevel = 4;  // 16 x 16-texel roots, four levels down to single elements

// Per node, in node_stats.comp's layout (4 vec4s), the first two (leafSlopes the last two): the area-weighted mean of
// `sent` (rgb), and where its light sits, the sums of w x and of w, w = luminance(sent) A (the origin of its
// visibility, as a shooter's: a node half under a block sends from its lit half).
std::vector<glm::vec4> nodeSources(const Atlas& atlas, const std::vector<ShooterNode>& nodes,
                                   const std::vector<glm::vec4>& sent) {
  std::vector<glm::vec4> out(nodes.size() * 4, glm::vec4(0.0f));
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const glm::ivec4 r = nodes[n].rect;
    glm::dvec3 sum(0.0), centre(0.0);
    double area = 0, weight = 0;
    for (int y = r.y; y < r.y + r.w; ++y)
      for (int x = r.x; x < r.x + r.z; ++x) {
        const std::size_t t = std::size_t(y) * atlas.width + x;
        if (atlas.polygonOf[t] == kNoPolygon || atlas.positionArea[t].w <= 0) continue;
        const double a = atlas.positionArea[t].w, l = luminance(glm::dvec3(glm::vec3(sent[t])));
        sum += glm::dvec3(glm::vec3(sent[t])) * a;
        area += a, weight += l * a;
        centre += glm::dvec3(atlas.positionArea[t]) * (l * a);
      }
    if (area <= 0) continue;
    out[n * 4] = glm::vec4(glm::vec3(sum / area), 0.0f);
    out[n * 4 + 1] = glm::vec4(glm::vec3(centre), float(weight));
  }
  return out;
}

// A single element's light changes across it (a wall's top element beside the ceiling sends little
// at the crease, more at its far side): per element of a planar projection chart, its half-axes
// (the cell's sides / 2, u x v along the chart's normal) and its luminance's change per element
// step along each, relative to its own (SlopeRule::Limited: minmod within its chart, one-sided at
// the chart's edge), which near_gather.glsl spreads over its quadrants. 0 elsewhere: constant.
void leafSlopes(const Atlas& atlas, const std::vector<ShooterNode>& nodes, const std::vector<glm::vec4>& sent,
                std::vector<glm::vec4>& out) {
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const glm::ivec4 r = nodes[n].rect;
    if (r.z != 1 || r.w != 1 || nodes[n].polygon == kNoPolygon) continue;
    const std::size_t t = std::size_t(r.y) * atlas.width + r.x;
    const Chart& chart = atlas.charts[atlas.chartOf[nodes[n].polygon]];
    const double own = luminance(glm::dvec3(glm::vec3(sent[t])));
    if (chart.uvMapped() || !chart.planar || atlas.positionArea[t].w <= 0 || own <= 0) continue;
    // Relative to its own light; quadrants at +-1/4 step stay >= 0.
    const glm::vec2 change = luminanceSlope(atlas, sent, {r.x, r.y}, SlopeRule::Limited);
    glm::dvec2 slope = glm::clamp(glm::dvec2(change) / own, -4.0, 4.0);
    glm::dvec3 hu = chart.frame.u * (chart.cellSize / 2), hv = chart.frame.v * (chart.cellSize / 2);
    if (glm::dot(glm::cross(hu, hv), glm::dvec3(nodes[n].normal)) < 0) std::swap(hu, hv), std::swap(slope.x, slope.y);
    out[n * 4 + 2] = glm::vec4(glm::vec3(hu), float(slope.x));
    out[n * 4 + 3] = glm::vec4(glm::vec3(hv), float(slope.y));
  }
}

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
  std::vector<glm::vec4> sources = nodeSources(atlas, tree.nodes, sent);
  leafSlopes(atlas, tree.nodes, sent, sources);
  sources_ = gl::Buffer(std::span<const glm::vec4>(sources));
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
