#include "src/reference/PathTracer.h"

#include <algorithm>

#include "gl/Limits.h"
#include "gl/State.h"
#include "src/base/Error.h"
#include "src/solver/Bvh.h"
#include "src/solver/EmitterTable.h"
#include "src/solver/ShaderContract.h"
#include "src/solver/VplTracer.h"

namespace hemirad {

namespace {
// Paths per pixel a dispatch: short dispatches keep a GPU's watchdog and llvmpipe's latency away,
// and the per-pixel sums are added in the same order whatever the chunk.
constexpr unsigned kSamplesPerDispatch = 16;
}  // namespace

void checkReferenceSettings(const ReferenceSettings& s) {
  if (s.batches < 2) throw InputError("--batches must be at least 2 (the standard error needs two)");
  if (s.samples % s.batches != 0)
    throw InputError("--spp " + std::to_string(s.samples) + " is not a multiple of --batches " +
                     std::to_string(s.batches) + ": every batch takes the same number of paths");
}

PathTracer::PathTracer(const Scene& scene) : bvh_(Bvh(scene)), program_(computeProgram("reference.comp")) {
  std::vector<glm::vec4> vertices;
  polygons_ = gl::Buffer(std::span<const GpuPolygon>(gpuPolygonTable(scene, vertices)));
  polygonVertices_ = gl::Buffer(std::span<const glm::vec4>(vertices));
  double power = 0;
  const std::vector<GpuEmitter> emitters = emitterTable(scene, power, "hemirad reference");
  emitters_ = gl::Buffer(std::span<const GpuEmitter>(emitters));
  program_.set("emitterCount", unsigned(emitters.size()));
  program_.set("totalPower", float(power));
}

void PathTracer::render(const Camera& camera, const ReferenceSettings& s, const BatchConsumer& consume) {
  checkReferenceSettings(s);
  const std::size_t pixels = std::size_t(s.width) * s.height;
  const unsigned perBatch = s.samples / s.batches;
  const Camera::PixelRays rays = camera.pixelRays(s.width, s.height);
  gl::Buffer sums(pixels * sizeof(glm::vec4));
  polygons_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGONS);
  polygonVertices_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_POLYGON_VERTICES);
  bvh_.bind();
  emitters_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_EMITTERS);
  sums.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_REFERENCE_SUMS);
  program_.set("width", unsigned(s.width));
  program_.set("height", unsigned(s.height));
  program_.set("seed", s.seed);
  program_.set("bounces", s.bounces);
  program_.set("eye", float(camera.eye.x), float(camera.eye.y), float(camera.eye.z));
  program_.set("corner", float(rays.corner.x), float(rays.corner.y), float(rays.corner.z));
  program_.set("dx", float(rays.dx.x), float(rays.dx.y), float(rays.dx.z));
  program_.set("dy", float(rays.dy.x), float(rays.dy.y), float(rays.dy.z));
  program_.use();
  std::vector<glm::vec4> batch(pixels);
  for (unsigned b = 0; b < s.batches; ++b) {
    sums.clear(0.0f);
    for (unsigned i = 0; i < perBatch; i += kSamplesPerDispatch) {
      program_.set("firstSample", b * perBatch + i);
      program_.set("samples", std::min(kSamplesPerDispatch, perBatch - i));
      gl::dispatchLinear(gl::groupsFor(unsigned(pixels), 64));
      gl::barrier(gl::Barrier::Storage);
    }
    gl::barrier(gl::Barrier::BufferUpdate);
    sums.read(0, pixels * sizeof(glm::vec4), batch.data());
    bvh_.requireWholeWalks("reference");
    consume(batch);
  }
}

}  // namespace hemirad
