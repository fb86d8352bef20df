#include "src/solver/VplTracer.h"

#include <algorithm>
#include <cmath>

#include "gl/Limits.h"
#include "gl/State.h"
#include "src/base/Error.h"
#include "src/solver/EmitterTable.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

struct GpuPathEnd {
  glm::vec4 escaped, behind;
};
static_assert(sizeof(GpuPathEnd) == 32);

double areaWeightedReflectance(const Scene& scene) {
  double sum = 0, area = 0;
  for (const ScenePolygon& p : scene.polygons()) {
    sum += p.area * luminance(scene.materials[p.material].reflectance);
    area += p.area;
  }
  return area > 0 ? std::clamp(sum / area, 0.0, 1.0) : 0.0;
}

}  // namespace

std::vector<GpuPolygon> gpuPolygonTable(const Scene& scene, std::vector<glm::vec4>& vertices) {
  std::vector<GpuPolygon> table;
  vertices.clear();
  for (const ScenePolygon& p : scene.polygons()) {
    const Material& m = scene.materials[p.material];
    table.push_back({glm::vec4(glm::vec3(p.normal), float(glm::dot(p.normal, p.vertices[0]))),
                     glm::vec4(glm::vec3(m.reflectance), 0), glm::vec4(glm::vec3(m.emission), 0),
                     glm::uvec4(unsigned(vertices.size()), unsigned(p.vertices.size()), 0, 0)});
    for (const glm::dvec3& v : p.vertices) vertices.push_back(glm::vec4(glm::vec3(v), 1));
  }
  return table;
}

VplLevels planLevels(unsigned vpls, double rhoAvg, int bounces) {
  const int deepest = std::clamp(bounces, 0, kMaxVplLevels - 1);
  auto sum = [&](unsigned n) {
    std::uint64_t s = 0;
    for (int j = 0; j <= deepest; ++j) s += std::uint64_t(std::floor(std::pow(rhoAvg, j) * n + 1e-9));
    return s;
  };
  // The largest n[0] whose levels fit in `vpls` (0 when even one path of every level would not:
  // then all `vpls` are direct paths).
  unsigned lo = 0, hi = vpls;
  while (lo < hi) {
    const unsigned mid = lo + (hi - lo + 1) / 2;
    if (sum(mid) <= vpls)
      lo = mid;
    else
      hi = mid - 1;
  }
  VplLevels levels;
  for (int j = 0; j <= deepest; ++j) levels.count[j] = unsigned(std::floor(std::pow(rhoAvg, j) * lo + 1e-9));
  levels.count[0] += vpls - unsigned(sum(lo));  // the remainder: more paths, each still unbiased
  unsigned offset = 0;
  for (int j = 0; j < kMaxVplLevels; ++j) {
    levels.offset[j] = offset;
    offset += levels.count[j];
    if (levels.count[j]) levels.deepest = j;
  }
  return levels;
}

VplTracer::VplTracer(const Scene& scene, const InstantSettings& settings)
    : scene_(scene), settings_(settings), bvh_(scene), program_(computeProgram("vpl_trace.comp")) {
  if (settings.vpls < 1) throw InputError("--vpls must be at least 1");
  rhoAvg_ = areaWeightedReflectance(scene);
  levels_ = planLevels(settings.vpls, rhoAvg_, settings.bounces);
  diagonal_ = glm::length(scene.boundsMax() - scene.boundsMin());
  std::vector<glm::vec4> vertices;
  const std::vector<GpuPolygon> table = gpuPolygonTable(scene, vertices);
  polygonVertices_ = gl::Buffer(std::span<const glm::vec4>(vertices));
  const std::vector<GpuEmitter> emitters = emitterTable(scene, emitted_, "--method instant");
  emitters_ = unsigned(emitters.size());
  polygons_ = gl::Buffer(std::span<const GpuPolygon>(table));
  bvhBuffers_ = BvhBuffers(bvh_);
  emitterTable_ = gl::Buffer(std::span<const GpuEmitter>(emitters));
  vpls_ = gl::Buffer(sizeof(GpuVpl) * settings.vpls);
  pathEnds_ = gl::Buffer(sizeof(GpuPathEnd) * levels_.count[0]);
  program_.set("levelCount", std::span<const unsigned>(levels_.count));
  program_.set("levelOffset", std::span<const unsigned>(levels_.offset));
  program_.set("emitterCount", emitters_);
}

void VplTracer::bind() const {
  polygons_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGONS);
  polygonVertices_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGON_VERTICES);
  vpls_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_VPLS);
}

void VplTracer::dispatch() {
  vpls_.clear(0u);  // slots of paths that ended early keep zero flux
  bind();
  bvhBuffers_.bind();
  emitterTable_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_EMITTERS);
  pathEnds_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PATH_ENDS);
  program_.set("seed", settings_.seed);
  program_.use();
  gl::dispatchLinear(gl::groupsFor(levels_.count[0], 64));
  gl::barrier(gl::Barrier::Storage | gl::Barrier::BufferUpdate);
}

VplStats VplTracer::trace() {
  dispatch();
  std::vector<GpuPathEnd> ends(levels_.count[0]);
  pathEnds_.read(0, ends.size() * sizeof(GpuPathEnd), ends.data());
  bvhBuffers_.requireWholeWalks("instant radiosity's VPL paths");
  VplStats s;
  s.vpls = settings_.vpls, s.paths = levels_.count[0], s.emitted = emitted_;
  for (const GpuPathEnd& e : ends) {
    s.escaped += luminance(glm::dvec3(e.escaped)), s.escapedPaths += e.escaped.w > 0;
    s.behind += luminance(glm::dvec3(e.behind)), s.behindPaths += e.behind.w > 0;
  }
  return s;
}

std::vector<GpuVpl> VplTracer::readVpls() const {
  std::vector<GpuVpl> out(settings_.vpls);
  vpls_.read(0, out.size() * sizeof(GpuVpl), out.data());
  return out;
}

}  // namespace hemirad
