#include "src/validate/FormFactorProbe.h"

#include <chrono>

#include "gl/Debug.h"
#include "gl/State.h"
#include "src/solver/Bvh.h"
#include "src/solver/Control.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

gl::Defines probeDefines(Projection projection, bool traced) {
  gl::Defines d = itemBufferDefines(projection);
  if (traced) d.push_back({"BVH_VISIBILITY", "1"});
  return d;
}

}  // namespace

FormFactorProbe::FormFactorProbe(const SolverState& state, int subdivision, int resolution, Projection projection,
                                 bool traced)
    : state_(state),
      itemBuffer_(state.scene, subdivision, resolution, state.farDistance, projection),
      program_(computeProgram("formfactor_probe.comp", probeDefines(projection, traced))),
      control_(sizeof(ControlBlock)),
      traced_(traced),
      result_(GL_RGBA32F, state.atlas.width, state.atlas.height) {
  if (traced) bvh_ = BvhBuffers(Bvh(state.scene));
  program_.set("farDistance", float(state.farDistance));
  program_.set("atlasSize", state.atlas.width, state.atlas.height);
}

std::vector<ProbeSample> FormFactorProbe::fromShooter(std::size_t s) {
  const Atlas& a = state_.atlas;
  const std::uint32_t polygon = a.polygonOf[s];
  const glm::dvec3 n = glm::normalize(glm::dvec3(a.normalOf[s]));
  ControlBlock c{};
  c.count = 1;
  ShooterRecord& shooter = c.shooter[0];
  for (int k = 0; k < 4; ++k) shooter.positionArea[k] = a.positionArea[s][k];
  {  // where it sees from, as scene.glsl's shooterEye: a centre behind its polygon's plane moved onto it
    const ScenePolygon& p = state_.scene.polygons()[polygon];
    const glm::dvec3 centre(a.positionArea[s]), onto = p.ontoPlane(centre);
    if (-p.height(centre) > 1e-4 * std::sqrt(double(a.positionArea[s].w)))
      for (int k = 0; k < 3; ++k) shooter.positionArea[k] = float(onto[k]);
  }
  shooter.normal[0] = float(n.x), shooter.normal[1] = float(n.y), shooter.normal[2] = float(n.z);
  shooter.rect[0] = int(s % a.width), shooter.rect[1] = int(s / a.width), shooter.rect[2] = shooter.rect[3] = 1;
  shooter.polygon = polygon;
  shooter.block = shooter.shape = 0;  // shape_ holds just this element's shape
  control_.upload(0, sizeof c, &c);
  const glm::ivec4 rect(shooter.rect[0], shooter.rect[1], 1, 1);
  shape_ = gl::Buffer(std::span<const glm::vec4>(shapeTable(state_.scene, a, {rect}).slots));

  gl::finish();
  auto t0 = std::chrono::steady_clock::now();
  if (traced_) {
    bindShooterLookup(state_, control_, shape_);
    bvh_.bind();
  } else {
    itemBuffer_.render(control_);
    itemBuffer_.bindForLookup(state_, control_, shape_);
  }
  result_.bindImage(slot::IMAGE_PROBE, GL_WRITE_ONLY);
  program_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(a.width), 16), gl::groupsFor(unsigned(a.height), 16));
  gl::barrier(gl::Barrier::TextureUpdate);
  gl::finish();
  gpuMs_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::vector<ProbeSample> out(a.polygonOf.size());
  result_.read(GL_RGBA, GL_FLOAT, out.size() * sizeof(ProbeSample), out.data());
  if (traced_) bvh_.requireWholeWalks("validate's traced visibility");
  gl::checkErrors("form factor probe");
  return out;
}

}  // namespace hemirad
