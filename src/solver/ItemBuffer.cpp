#include "src/solver/ItemBuffer.h"

#include "gl/State.h"
#include "src/base/Error.h"
#include "src/scene/Atlas.h"
#include "src/scene/ItemMesh.h"
#include "src/solver/ShaderContract.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hemirad {

namespace {

// Triangles a chunk of the item mesh holds: few enough that a shooter skips most of a large scene,
// many enough that a pass's draws stay few (real_400k: 400 chunks x 80 layers).
constexpr std::size_t kChunkTriangles = 1024;

// Consecutive triangles of the index list in chunks, each with its bounds and index range, as
// cull_items.comp reads them.
std::vector<glm::vec4> itemChunks(const IndexedItemMesh& mesh) {
  std::vector<glm::vec4> out;
  for (std::size_t first = 0; first < mesh.indices.size(); first += 3 * kChunkTriangles) {
    const std::size_t count = std::min(3 * kChunkTriangles, mesh.indices.size() - first);
    glm::vec3 lo(3.4e38f), hi(-3.4e38f);
    for (std::size_t i = first; i < first + count; ++i) {
      const ItemVertex& v = mesh.vertices[mesh.indices[i]];
      lo = glm::min(lo, glm::vec3(v.x, v.y, v.z)), hi = glm::max(hi, glm::vec3(v.x, v.y, v.z));
    }
    out.push_back(glm::vec4(lo, glm::uintBitsToFloat(unsigned(first))));
    out.push_back(glm::vec4(hi, glm::uintBitsToFloat(unsigned(count))));
  }
  return out;
}

int faceSide(int resolution, Projection p) {
  return p == Projection::Hemicube ? std::max(1, int(std::lround(resolution / std::sqrt(3.0)))) : resolution;
}
}  // namespace

// hemisphere.glsl's switch; the orthographic map (seed 003's) is the one with none.
gl::Defines itemBufferDefines(Projection p) {
  switch (p) {
    case Projection::Hemicube:
      return {{"HEMICUBE", "1"}};
    case Projection::Conformal:
      return {{"CONFORMAL", "1"}};
    case Projection::EqualArea:
      return {{"EQUAL_AREA", "1"}};
    case Projection::Orthographic:
      break;
  }
  return {};
}

ItemBuffer::ItemBuffer(const Scene& scene, int subdivision, int resolution, double farDistance, Projection projection,
                       int shooters)
    : projection_(projection),
      faceResolution_(faceSide(resolution, projection)),
      faces_(projection == Projection::Hemicube ? 5 : 1),
      shooters_(shooters),
      defines_(itemBufferDefines(projection)),
      program_(renderProgram("itembuffer.vert", "itembuffer.frag", defines_)),
      cull_(computeProgram("cull_items.comp", defines_)),
      id_(GL_R32UI, faceResolution_, faceResolution_, faces_ * shooters_),
      depth_(GL_DEPTH_COMPONENT32F, faceResolution_, faceResolution_, faces_ * shooters_) {
  const IndexedItemMesh mesh = indexItemMesh(buildItemMesh(scene, subdivision));
  indexCount_ = mesh.indices.size();
  vertices_ = gl::Buffer(std::span<const ItemVertex>(mesh.vertices));
  indices_ = gl::Buffer(std::span<const std::uint32_t>(mesh.indices));
  vao_.vertexBuffer(vertices_, sizeof(ItemVertex));
  vao_.indexBuffer(indices_);
  vao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  vao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  const std::vector<glm::vec4> chunks = itemChunks(mesh);
  chunkCount_ = chunks.size() / 2;
  const std::size_t layers = std::size_t(faces_) * std::size_t(shooters_);
  std::vector<std::uint32_t> layerIds(layers);
  for (std::size_t i = 0; i < layers; ++i) layerIds[i] = std::uint32_t(i);
  layers_ = gl::Buffer(std::span<const std::uint32_t>(layerIds));
  vao_.instanceUintAttribute(2, layers_);
  if (chunkCount_) {
    chunks_ = gl::Buffer(std::span<const glm::vec4>(chunks));
    commands_ = gl::Buffer(chunkCount_ * layers * 5 * sizeof(std::uint32_t));  // DrawElementsIndirectCommand
  }
  target_.attach(GL_COLOR_ATTACHMENT0, id_);
  target_.attach(GL_DEPTH_ATTACHMENT, depth_);
  target_.checkComplete("item buffer");
  program_.set("farDistance", float(farDistance));
  cull_.set("farDistance", float(farDistance));
  cull_.set("chunkCount", unsigned(chunkCount_));
  program_.set("faceSize", float(faceResolution_));
  std::vector<glm::vec4> planes;  // by item id: the polygons, then the wholes (Scene::occluder)
  for (std::size_t id = 0; id < scene.occluderCount(); ++id) {
    const ScenePolygon& p = scene.occluder(id);
    planes.push_back(glm::vec4(glm::vec3(p.normal), float(glm::dot(p.normal, p.vertices[0]))));
  }
  planes_ = gl::Buffer(std::span<const glm::vec4>(planes));
}

void ItemBuffer::render(const gl::Buffer& control) {
  control.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CONTROL);
  if (chunkCount_) {
    chunks_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_ITEM_CHUNKS);
    commands_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_ITEM_COMMANDS);
    cull_.use();
    gl::Program::dispatch(unsigned((chunkCount_ + 63) / 64), unsigned(faces_ * shooters_));
    gl::barrier(gl::Barrier::Command);
  }
  // Every face occludes from both sides (no culling); the hemisphere clips at the horizon.
  // The hemicube's depth is reversed (hemisphere.glsl: itemClipPosition).
  const bool reversed = projection_ == Projection::Hemicube;
  gl::RasterState{.width = faceResolution_,
                  .height = faceResolution_,
                  .depthFunc = reversed ? gl::DepthFunc::Greater : gl::DepthFunc::Less,
                  .depthRange = reversed ? gl::DepthRange::Reversed : gl::DepthRange::Standard,
                  .clipDistance0 = true}
      .apply();
  planes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PLANES);
  program_.use();
  vao_.bind();
  target_.clearColor(kNoPolygon);  // every layer
  target_.clearDepth(reversed ? 0.0f : 1.0f);
  target_.bind();
  if (chunkCount_) gl::drawIndexedIndirect(commands_, chunkCount_ * std::size_t(faces_) * std::size_t(shooters_));
}

void bindShooterLookup(const SolverState& state, const gl::Buffer& control, const gl::Buffer& shapes) {
  state.bindScene();
  control.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CONTROL);
  shapes.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOOTER_SHAPES);
}

void ItemBuffer::bindForLookup(const SolverState& state, const gl::Buffer& control, const gl::Buffer& shapes) const {
  bindShooterLookup(state, control, shapes);
  id_.bindUnit(slot::SAMPLER_ITEM_ID);
}

}  // namespace hemirad
