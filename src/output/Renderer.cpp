#include "src/output/Renderer.h"

#include <algorithm>

#include <fmt/format.h>

#include "gl/Backend.h"
#include "gl/Debug.h"
#include "gl/Limits.h"
#include "gl/State.h"
#include "src/output/CameraTarget.h"
#include "src/output/DirectShares.h"
#include "src/output/Supersample.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {
// llvmpipe's first try at a near-gathered view: the Cornell box's gather took 16 shares at 1,000
// elements (64^2); a draw more than needed costs a raster pass, a cut try the whole view (there
// 9.5 s for the per-pixel pass from 1 share, 4.2 s from 16, the same bytes). The direct light
// starts in one draw.
constexpr SharePlan kFirstSoftwareShares{1, 16};
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
// near gather, in the draws of shares_ (src/output/DirectShares.h). A draw can cost seconds, so
// each is drawn in bands (src/output/DrawBands.h). Stops at the first part whose walks were cut.
Renderer::Cut Renderer::drawDirect(const glm::mat4& vp, int width, int height) {
  gl::RasterState add = gl::cameraView(width, height);
  add.depthFunc = gl::DepthFunc::Equal, add.depthWrite = false, add.additiveBlend = true;
  direct_->bind(directProgram_);
  if (gather_) gather_->bind(directProgram_);
  directProgram_.set("directPass", 1);
  directProgram_.set("viewProjection", &vp[0][0]);
  const std::vector<DirectShare> shares =
      directShares(*shares_, direct_->pieces(), direct_->grid(), gather_ ? gather_->blocks() : 0);
  const auto lights = [](const DirectShare& s) { return s.stripsEnd > s.stripsFirst; };
  for (std::size_t k = 0; k < shares.size(); ++k) {
    direct_->bindStrips(directProgram_, shares[k].stripsFirst, shares[k].stripsEnd);
    if (gather_) gather_->bindBlocks(directProgram_, shares[k].blocksFirst, shares[k].blocksEnd);
    directProgram_.use();
    drawInBands(bands_, width, height, [&](const gl::Rect& band) {
      add.scissor = band;
      add.apply();
      mesh_.draw();
    });
    // Split, each part's walks are read once it is drawn, so a retry splits the part that was cut;
    // one draw of both (every GPU) is read once a view, by render().
    const bool partDone = shares.size() > 1 && (k + 1 == shares.size() || lights(shares[k]) != lights(shares[k + 1]));
    if (partDone && direct_->walks().walksCut()) return lights(shares[k]) ? Cut::Direct : Cut::Gather;
  }
  gl::checkErrors("per-pixel direct light");
  return Cut::None;
}

// llvmpipe ends all of a shader invocation's loops after 65,535 turns in all (shaders/bvh.glsl),
// which a pixel's walks to the emitters or its near gather beside a crease can pass: where a
// part's walks were cut, the view is drawn again with that part in 4 x as many shares, each
// walking less, down to a strip or a block a draw. A renderer starts from the shares its last view
// took (the same scene's views need about as many), its first on llvmpipe from
// kFirstSoftwareShares.
Image Renderer::render(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues) {
  const bool direct = direct_ && &atlasValues == &shown();  // other values (error maps) are shown as they are
  Cut cut = Cut::None;
  if (!direct) return draw(camera, width, height, supersample, atlasValues, false, cut);
  if (!shares_) shares_ = gl::softwareRenderer() ? kFirstSoftwareShares : SharePlan{};
  const SharePlan most{std::max(direct_->strips(), 1u), std::max(gather_ ? gather_->blocks() : 0u, 1u)};
  for (;;) {
    Image view = draw(camera, width, height, supersample, atlasValues, true, cut);
    if (cut == Cut::None && direct_->walks().walksCut()) cut = Cut::Both;  // drawn in one draw
    if (cut == Cut::None) return view;
    const bool moreDirect = cut != Cut::Gather && shares_->direct < most.direct;
    const bool moreGather = cut != Cut::Direct && shares_->gather < most.gather;
    if (!moreDirect && !moreGather)  // throws
      direct_->walks().requireWholeWalks(
          cut == Cut::Gather ? "the camera image's near gather, a block a draw (--final-gather off leaves it out)"
                             : "the camera image's per-pixel light, a strip a draw");
    if (moreDirect) shares_->direct = std::min(most.direct, shares_->direct * 4);
    if (moreGather) shares_->gather = std::min(most.gather, shares_->gather * 4);
    direct_->walks().clearWalksCut();
  }
}

// One view, with the per-pixel pass where `perPixel`; where its walks were cut, none, and `cut` says
// which part's.
Image Renderer::draw(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues,
                     bool perPixel, Cut& cut) {
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
  const gl::Program& program = perPixel ? directProgram_ : program_;
  program.set("addAmbient", int(ambient));
  std::vector<double> sums;
  std::vector<float> rgba;
  for (int k = 0; k < grid.draws(); ++k) {
    target.clearAndBind();
    gl::cameraView(w, h).apply();
    const glm::mat4 shifted = grid.shift(k, w, h) * vp;
    program.set("viewProjection", &shifted[0][0]);
    if (perPixel) program.set("directPass", 0);
    program.use();
    mesh_.draw();
    gl::checkErrors("camera render");
    if (perPixel && (cut = drawDirect(shifted, w, h)) != Cut::None) return {};
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
