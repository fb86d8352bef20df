#include "src/solver/SolverState.h"

#include <cstring>
#include <string>

#include "src/base/Error.h"
#include "src/base/Hash.h"
#include "src/scene/Clusters.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {
struct GpuPolygon {
  glm::vec4 plane, reflectance, emission;  // plane: unit normal, offset n . p; reflectance.w: clusterReachBehind
  glm::uvec4 vertices;                     // first, count in polygonVertices; chart; in a cluster
};

}  // namespace

SolverState::SolverState(const Scene& s, const Atlas& a)
    : scene(s),
      atlas(a),
      positionArea(GL_RGBA32F, a.width, a.height),
      polygonOf(GL_R32UI, a.width, a.height),
      normal(GL_RGBA32F, a.width, a.height),
      radiosity(GL_RGBA32F, a.width, a.height),
      deltaB(GL_RGBA32F, a.width, a.height) {
  std::vector<GpuPolygon> table;
  std::vector<glm::vec4> vertices;
  const std::vector<float> behind = clusterReachBehind(s, a);
  for (std::size_t id = 0; id < s.occluderCount(); ++id) {  // the polygons, then the wholes (Scene.h)
    const ScenePolygon& p = s.occluder(id);
    const Material& m = s.materials[p.material];
    const std::uint32_t chart = id < a.chartOf.size() ? a.chartOf[id] : kNoPolygon;  // a whole is no chart's
    table.push_back({glm::vec4(glm::vec3(p.normal), float(glm::dot(p.normal, p.vertices[0]))),
                     glm::vec4(glm::vec3(m.reflectance), behind[id]), glm::vec4(glm::vec3(m.emission), 0),
                     glm::uvec4(unsigned(vertices.size()), unsigned(p.vertices.size()), chart,
                                unsigned(chart != kNoPolygon && a.charts[chart].clustered))});
    for (auto& v : p.vertices) vertices.push_back(glm::vec4(glm::vec3(v), 1));
  }
  polygons = gl::Buffer(std::span<const GpuPolygon>(table));
  polygonVertices = gl::Buffer(std::span<const glm::vec4>(vertices));
  positionArea.upload(GL_RGBA, GL_FLOAT, a.positionArea.data());
  polygonOf.upload(GL_RED_INTEGER, GL_UNSIGNED_INT, a.polygonOf.data());
  std::vector<glm::vec4> normals(a.normalOf.size());
  for (std::size_t t = 0; t < normals.size(); ++t) normals[t] = glm::vec4(a.normalOf[t], 0.0f);
  normal.upload(GL_RGBA, GL_FLOAT, normals.data());

  std::vector<glm::vec4> emission(a.positionArea.size(), glm::vec4(0.0f));
  for (size_t t = 0; t < emission.size(); ++t) {
    if (a.polygonOf[t] == kNoPolygon) continue;
    glm::dvec3 e = s.materials[s.polygons()[a.polygonOf[t]].material].emission;
    emission[t] = glm::vec4(glm::vec3(e), 0.0f);
    emittedPower += luminance(e) * a.positionArea[t].w;
  }
  radiosity.upload(GL_RGBA, GL_FLOAT, emission.data());
  deltaB.upload(GL_RGBA, GL_FLOAT, emission.data());
  farDistance = 2.0 * glm::length(s.boundsMax() - s.boundsMin()) + 1e-6;
}

void SolverState::bindScene() const {
  polygons.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGONS);
  polygonVertices.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGON_VERTICES);
  positionArea.bindUnit(slot::SAMPLER_ATLAS_POSITION_AREA);
  polygonOf.bindUnit(slot::SAMPLER_ATLAS_POLYGON);
  normal.bindUnit(slot::SAMPLER_ATLAS_NORMAL);
}

bool fitsShapeTable(const std::vector<Poly3>& shape) {
  bool ok = !shape.empty() && shape.size() <= std::size_t(kMaxShapePieces);
  for (const Poly3& piece : shape) ok = ok && piece.size() >= 3 && piece.size() <= std::size_t(kMaxShapeVertices);
  return ok;
}

ShapeTable shapeTable(const Scene& scene, const Atlas& atlas, const std::vector<glm::ivec4>& rects) {
  ShapeTable out;
  out.slots.assign(rects.size() * kShapeStride, glm::vec4(0.0f));
  std::vector<std::uint32_t> polygonOf;  // a cluster's pieces': their polygons (+ 1 in w: formfactor.glsl's clusterEye)
  auto write = [&](std::size_t base, const Poly3& piece, std::size_t k) {
    out.slots[base] =
        glm::vec4(float(piece.size()), 0, 0, glm::uintBitsToFloat(k < polygonOf.size() ? polygonOf[k] + 1 : 0u));
    for (std::size_t i = 0; i < piece.size(); ++i) out.slots[base + 1 + i] = glm::vec4(glm::vec3(piece[i]), 1);
  };
  for (std::size_t b = 0; b < rects.size(); ++b) {
    const std::uint32_t chart = atlas.chartUnder(rects[b]);
    const bool cluster = chart != kNoPolygon && atlas.charts[chart].clustered;
    polygonOf.clear();
    std::vector<Poly3> shape =
        cluster ? atlas.blockShape(scene, rects[b], &polygonOf) : atlas.blockOutline(scene, rects[b]);
    if (shape.size() == 1 && !fitsShapeTable(shape))
      shape = atlas.blockShape(scene, rects[b]);  // an outline of many corners
    if (!fitsShapeTable(shape)) {                 // count 0: the gather takes the disc form factor
      out.discShapes += !shape.empty();
      continue;
    }
    std::size_t previous = b * kShapeStride;
    write(previous, shape[0], 0);
    out.slots[previous].y = glm::uintBitsToFloat(unsigned(shape.size()));
    for (std::size_t k = 1; k < shape.size(); ++k) {  // packed: a piece takes its vertices + 1 vec4s
      const std::size_t base = out.slots.size();
      out.slots.resize(base + 1 + shape[k].size());
      write(base, shape[k], k);
      out.slots[previous].z = glm::uintBitsToFloat(unsigned(base));
      previous = base;
    }
  }
  return out;
}

static std::vector<glm::vec4> readRgba(const gl::Texture& t) {
  std::vector<glm::vec4> out(size_t(t.width()) * t.height());
  t.read(GL_RGBA, GL_FLOAT, out.size() * sizeof(glm::vec4), out.data());
  return out;
}
std::vector<glm::vec4> SolverState::readRadiosity() const { return readRgba(radiosity); }
std::vector<glm::vec4> SolverState::readDeltaB() const { return readRgba(deltaB); }

void SolverState::restore(const std::vector<glm::vec4>& B, const std::vector<glm::vec4>& dB) {
  const std::size_t n = std::size_t(atlas.width) * atlas.height;
  if (B.size() != n || dB.size() != n)
    throw InputError("checkpoint holds " + std::to_string(B.size()) + " elements, the atlas " + std::to_string(n));
  radiosity.upload(GL_RGBA, GL_FLOAT, B.data());
  deltaB.upload(GL_RGBA, GL_FLOAT, dB.data());
}

std::vector<ObjectRadiosity> objectRadiosity(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B) {
  std::vector<ObjectRadiosity> out(scene.objects.size());
  for (size_t i = 0; i < out.size(); ++i) out[i].name = scene.objects[i].name;
  for (size_t t = 0; t < B.size(); ++t) {
    if (atlas.polygonOf[t] == kNoPolygon) continue;
    ObjectRadiosity& o = out[scene.polygons()[atlas.polygonOf[t]].object];
    double a = atlas.positionArea[t].w;
    o.area += a;
    o.mean += glm::dvec3(B[t]) * a;
  }
  for (auto& o : out)
    if (o.area > 0) o.mean /= o.area;
  return out;
}

std::uint64_t radiosityHash(const Atlas& atlas, const std::vector<glm::vec4>& B) {
  Fnv1a h;
  for (size_t t = 0; t < B.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon) h.add(&B[t][0], 3 * sizeof(float));
  return h.value();
}

}  // namespace hemirad
