#include "src/walk/VplError.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <map>

#include "src/base/AtomicFile.h"
#include "src/base/OutputPaths.h"
#include "src/output/Figure.h"
#include "src/output/ImageFile.h"
#include "src/output/InstantRenderer.h"
#include "src/output/Renderer.h"
#include "src/scene/Camera.h"
#include "src/solver/ProgressiveSolver.h"

namespace hemirad {

namespace {

double pixelLuminance(const Image& image, std::size_t p) {
  return luminance(glm::dvec3(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]));
}

// Mean over each region's pixels of |L - L_ref| / L_ref (pixels the reference leaves black are
// left out), and of the signed (L - L_ref) / L_ref, where noise cancels and bias stays; the last
// entry of each is over every region's pixels together.
struct RegionErrors {
  std::vector<double> absolute, signedMean;
};
RegionErrors regionErrors(const Scene& scene, const std::vector<std::uint32_t>& polygon, const Image& image,
                          const Image& reference) {
  const std::size_t regions = scene.objects.size();
  RegionErrors e{std::vector<double>(regions + 1, 0.0), std::vector<double>(regions + 1, 0.0)};
  std::vector<double> count(regions + 1, 0.0);
  for (std::size_t p = 0; p < polygon.size(); ++p) {
    const double ref = pixelLuminance(reference, p);
    if (polygon[p] == kNoPolygon || ref <= 1e-12) continue;
    const double d = (pixelLuminance(image, p) - ref) / ref;
    for (std::size_t r : {std::size_t(scene.polygons()[polygon[p]].object), regions})
      e.absolute[r] += std::abs(d), e.signedMean[r] += d, count[r] += 1;
  }
  for (std::size_t r = 0; r <= regions; ++r)
    if (count[r] > 0) e.absolute[r] /= count[r], e.signedMean[r] /= count[r];
  return e;
}

Image converged(const Scene& scene, const VplErrorOptions& o, const Camera& camera, int maxTexture) {
  const Atlas atlas = buildAtlas(scene, o.discretisation, maxTexture);  // its charts, as the flags say
  SolverState state(scene, atlas);
  ProgressiveSettings p;
  p.stop = {0, o.referenceConvergence};
  p.timings = gl::TimerMode::Off;
  ProgressiveSolver solver(state, p);
  advanceToStop(solver, {});
  return Renderer(state).render(camera, o.width, o.height, 1);
}

Image sideBySide(const Image& left, const Image& right) {
  Image out{left.width * 2, left.height, std::vector<float>(left.rgb.size() * 2)};
  for (int y = 0; y < left.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const Image& from = x < left.width ? left : right;
        out.rgb[(std::size_t(y) * out.width + x) * 3 + c] =
            from.rgb[(std::size_t(y) * left.width + x % left.width) * 3 + c];
      }
  return out;
}

}  // namespace

int runVplError(VplErrorOptions o) {
  if (o.out.empty()) o.out = freshFolder("hemirad-compare-vpls");  // no --out-dir
  fmt::print(stderr, "hemirad: writing into {}\n", o.out);
  checkPlotting();
  parseFigureSize(o.figureSize);  // a bad size fails before the solves
  Scene scene = loadScene(o.scene, o.load);
  validateSolvable(scene);
  const Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  std::filesystem::create_directories(o.out);
  const Image reference = converged(scene, o, camera, backend->maxTextureSize());

  const std::string name = std::filesystem::path(o.scene).stem().string();
  std::string csv = "vpls,paths,clamp_bias,escaped_fraction,render_ms";
  std::string table = "| VPLs | paths | clamp bias | escaped |";
  for (const SceneObject& object : scene.objects) csv += ",error_" + object.name, table += " " + object.name + " |";
  csv += ",error_image";
  for (const SceneObject& object : scene.objects) csv += ",signed_" + object.name;
  csv += ",signed_image\n", table += " image |\n|---|---|---|---|";
  for (std::size_t r = 0; r <= scene.objects.size(); ++r) table += "---|";
  table += "\n";
  std::vector<PlotSeries> series(scene.objects.size() + 1);
  for (std::size_t r = 0; r < scene.objects.size(); ++r) series[r].label = scene.objects[r].name;
  series.back().label = "whole image";
  Image last;
  for (unsigned vpls : o.vpls) {
    InstantSettings s = o.instant;
    s.vpls = vpls;
    const auto t0 = std::chrono::steady_clock::now();
    VplTracer tracer(scene, s);
    const VplStats stats = tracer.trace();
    InstantRenderer renderer(scene, tracer, s);
    const InstantImage render = renderer.render(camera, o.width, o.height, 1, Shading::Deferred);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    const RegionErrors region = regionErrors(scene, renderer.visiblePolygons(), render.image, reference);
    const std::vector<double>& errors = region.absolute;
    const double escaped = stats.emitted > 0 ? stats.escaped / stats.emitted : 0.0;
    csv += fmt::format("{},{},{:.6g},{:.6g},{:.1f}", vpls, stats.paths, render.clampBias(), escaped, ms);
    table +=
        fmt::format("| {} | {} | {:.2f} % | {:.2f} % |", vpls, stats.paths, 100 * render.clampBias(), 100 * escaped);
    for (std::size_t r = 0; r < errors.size(); ++r) {
      csv += fmt::format(",{:.6g}", errors[r]);
      table += fmt::format(" {:.4f} |", errors[r]);
      series[r].x.push_back(vpls), series[r].y.push_back(errors[r]);
    }
    for (double signedError : region.signedMean) csv += fmt::format(",{:.6g}", signedError);
    csv += "\n", table += "\n";
    last = render.image;
    fmt::print(stderr, "hemirad: {}: {} VPLs, image error {:.4f} ({:.0f} ms)\n", name, vpls, errors.back(), ms);
  }
  writeTextFile(o.out + "/" + name + "_vpl_error.csv", csv);
  writeTextFile(o.out + "/" + name + "_vpl_error.md", table);
  Figures figures(provenance(backend->name(), backend->renderer()), parseFigureSize(o.figureSize));
  figures.add(o.out + "/" + name + "_vpl_error",
              LinePlot{fmt::format("{}: instant radiosity vs progressive ({} x {} px)", name, o.width, o.height),
                       "VPLs", "mean relative luminance error per pixel", true, true, series});
  figures.write();
  if (!o.sideBySide.empty()) writePng(o.sideBySide, sideBySide(last, reference), exposureScale(reference, 0));
  fmt::print("{}", table);
  return 0;
}

}  // namespace hemirad
