#include "src/output/Renderer.h"

#include <algorithm>

#include <fmt/format.h>

#include "gl/Backend.h"
#include "gl/Debug.h"
#include "gl/Limits.h"
#include "gl/State.h"
#include "src/output/CameraTarget.h"
#include "src/output/Supersample.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {
// llvmpipe's first try at a near-gathered view: the Cornell box's gather took 16 shares at 1,000
// elements (64^2); a draw more than needed costs a raster pass, a cut try the whole view (there
// 9.5 s for the per-pixel pass from 1 share, 4.2 s from 16, the same bytes).
constexpr unsigned kFirstSoftwareShares = 16;
}  // namespace

void requireDrawn(const std::vector<float>& rgba) {
  for (std::size_t i = 3; i < rgba.size(); i += 4)
    if (rgba[i] != 1.0f)
      throw gl::Error(fmt::format(
          "camera render: the GPU returned pixel {} with alpha {} (every pixel's is 1): its draws were lost", i / 4,
          rgba[i]));
}

Renderer::Renderer(const SolverState& state)
    : state_(state),
      program_(renderProgram("camera.vert", "camera.frag")),
      ambientProgram_(computeProgram("ambient.comp")),
      ambientTerm_(sizeof(glm::vec4)),
      mesh_(state.scene, state.atlas) {
  // Seed 004: a unit of light meets rho_avg (area-weighted) at each bounce, so all of them
  // together hand on R = 1 + rho_avg + rho_avg^2 + ... = 1 / (1 - rho_avg).
  glm::dvec3 rhoArea(0.0);
  double area = 0;
  for (std::size_t t = 0; t < state.atlas.polygonOf.size(); ++t) {
    if (state.atlas.polygonOf[t] == kNoPolygon) continue;
    const double a = state.atlas.positionArea[t].w;
    rhoArea += a * state.scene.materials[state.scene.polygons()[state.atlas.polygonOf[t]].material].reflectance;
    area += a;
  }
  const glm::dvec3 rhoAvg = area > 0 ? rhoArea / area : glm::dvec3(0.0);
  const glm::vec3 interreflection(1.0 / (1.0 - glm::min(rhoAvg, glm::dvec3(0.999))));
  ambientProgram_.set("interreflection", interreflection.x, interreflection.y, interreflection.z);
  ambientProgram_.set("totalArea", float(area));
}

void Renderer::updateAmbient() {
  gl::barrier(gl::Barrier::Image | gl::Barrier::TextureFetch);
  state_.bindScene();
  state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);  // importance I in alpha: view-driven weighting
  state_.deltaB.bindImage(slot::IMAGE_DELTA_B, GL_READ_ONLY);
  ambientTerm_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_AMBIENT);
  ambientProgram_.use();
  gl::Program::dispatch(1);
  gl::barrier(gl::Barrier::Storage | gl::Barrier::BufferUpdate);
}

glm::vec3 Renderer::ambientTerm() {
  updateAmbient();
  glm::vec4 a;
  ambientTerm_.read(0, sizeof a, &a);
  return glm::vec3(a);
}

Image Renderer::render(const Camera& camera, int width, int height, int supersample) {
  if (stitcher_) show((*stitcher_)(state_.readRadiosity()));
  return render(camera, width, height, supersample, shown());
}

void Renderer::stitchLive() {
  auto shown = std::make_unique<ShownRadiosity>(state_.scene, state_.atlas);
  if (!shown->identity()) stitcher_ = std::move(shown);
}

void Renderer::show(const std::vector<glm::vec4>& values) {
  if (!shown_) shown_ = std::make_unique<gl::Texture>(GL_RGBA32F, state_.atlas.width, state_.atlas.height);
  shown_->upload(GL_RGBA, GL_FLOAT, values.data());
}

void Renderer::usePerPixelDirect(const DirectLight& direct, const NearGather* gather) {
  direct_ = &direct;
  gather_ = gather;
  gl::Defines defines = DirectLight::defines();
  if (gather) {
    const gl::Defines more = NearGather::defines();
    defines.insert(defines.end(), more.begin(), more.end());
  }
  directProgram_ = renderProgram("camera.vert", "camera.frag", defines);
}

// The second pass of a per-pixel-direct view: each visible fragment (the depths the first pass
// left, GL_EQUAL: the same program and vertices give the same depths) adds its direct light and
// near gather. It can cost seconds, so it is drawn in bands (src/output/DrawBands.h). In `parts`
// > 1 the direct light is drawn alone, then the gather's blocks in `parts` shares, one a draw.
void Renderer::drawDirect(const glm::mat4& vp, int width, int height, unsigned parts) {
  gl::RasterState add = gl::cameraView(width, height);
  add.depthFunc = gl::DepthFunc::Equal, add.depthWrite = false, add.additiveBlend = true;
  direct_->bind(directProgram_);
  if (gather_) gather_->bind(directProgram_);
  directProgram_.set("directPass", 1);
  directProgram_.set("viewProjection", &vp[0][0]);
  const unsigned blocks = gather_ ? gather_->blocks() : 0, draws = parts == 1 ? 1 : parts + 1;
  const bool cutBefore = parts > 1 && direct_->walks().walksCut();  // by an earlier grid draw's shares
  for (unsigned d = 0; d < draws; ++d) {
    directProgram_.set("addDirect", int(d == 0));
    if (gather_ && parts > 1)
      gather_->bindBlocks(directProgram_, d ? blocks * (d - 1) / parts : 0, d ? blocks * d / parts : 0);
    directProgram_.use();
    drawInBands(bands_, width, height, [&](const gl::Rect& band) {
      add.scissor = band;
      add.apply();
      mesh_.draw();
    });
    // Drawn alone, the direct light's walks were cut: no share of the gather helps (render()).
    if (parts > 1 && d == 0 && !cutBefore)
      direct_->walks().requireWholeWalks("the camera image's per-pixel direct light");
  }
  gl::checkErrors("per-pixel direct light");
}

// llvmpipe ends all of a shader invocation's loops after 65,535 turns in all (shaders/bvh.glsl),
// which a pixel's near gather beside a crease can pass: where a walk was cut, the view is drawn
// again with the gather in 4 x as many shares, each walking less, down to a block a draw. A
// renderer starts from the shares its last view took (the same scene's views need about as many),
// its first on llvmpipe from kFirstSoftwareShares.
Image Renderer::render(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues) {
  const bool direct = direct_ && &atlasValues == &shown();  // other values (error maps) are shown as they are
  if (!direct) return draw(camera, width, height, supersample, atlasValues, 0);
  const unsigned most = gather_ ? std::max(gather_->blocks(), 1u) : 1;
  const unsigned first = lastShares_ ? lastShares_ : gl::softwareRenderer() ? kFirstSoftwareShares : 1;
  for (unsigned parts = std::min(most, first);; parts = std::min(most, parts * 4)) {
    Image view = draw(camera, width, height, supersample, atlasValues, parts);
    lastShares_ = parts;
    if (!direct_->walks().walksCut()) return view;
    if (parts == most) direct_->walks().requireWholeWalks("the camera image's per-pixel light");  // throws
    direct_->walks().clearWalksCut();
  }
}

// One view; `parts`: 0 without per-pixel direct light, else drawDirect's.
Image Renderer::draw(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues,
                     unsigned parts) {
  const CameraPlan plan = cameraPlan(width, height, supersample, samples_, gl::limits().textureSize);
  const SupersampleGrid grid(supersample, plan.scale);
  const int w = width * grid.scale(), h = height * grid.scale();
  CameraTarget target(w, h, plan.samples);
  lastSamples_ = plan.samples;
  const glm::mat4 vp = mesh_.viewProjection(camera, double(width) / height);
  gl::barrier(gl::Barrier::TextureFetch);
  state_.bindScene();
  atlasValues.bindUnit(slot::SAMPLER_ATLAS_VALUES);
  const bool ambient = ambient_ && &atlasValues == &shown();
  if (ambient) updateAmbient();
  ambientTerm_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_AMBIENT);
  const bool direct = parts > 0;
  const gl::Program& program = direct ? directProgram_ : program_;
  program.set("addAmbient", int(ambient));
  std::vector<double> sums;
  std::vector<float> rgba;
  for (int k = 0; k < grid.draws(); ++k) {
    target.clearAndBind();
    gl::cameraView(w, h).apply();
    const glm::mat4 shifted = grid.shift(k, w, h) * vp;
    program.set("viewProjection", &shifted[0][0]);
    if (direct) program.set("directPass", 0);
    program.use();
    mesh_.draw();
    gl::checkErrors("camera render");
    if (direct) drawDirect(shifted, w, h, parts);
    target.read(rgba);
    requireDrawn(rgba);
    grid.accumulate(rgba, width, height, 3, sums);
  }
  const double norm = 1.0 / (double(grid.scale()) * grid.scale() * grid.draws());
  Image img{width, height, std::vector<float>(sums.size())};
  for (std::size_t i = 0; i < sums.size(); ++i) img.rgb[i] = float(sums[i] * norm);
  return img;
}

}  // namespace hemirad
