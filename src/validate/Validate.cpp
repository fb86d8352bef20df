#include "src/validate/Validate.h"

#include "src/output/Figure.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <numeric>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Figure.h"
#include "src/output/Provenance.h"
#include "src/scene/Camera.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/ShootingPlan.h"
#include "src/validate/DenseSolver.h"
#include "src/validate/ExactReference.h"
#include "src/validate/FormFactorProbe.h"

namespace hemirad {

namespace {

double percentile(std::vector<double>& v, double q) {
  if (v.empty()) return 0;
  auto k = v.begin() + std::ptrdiff_t(q * double(v.size() - 1) + 0.5);
  std::nth_element(v.begin(), k, v.end());
  return *k;
}

// F_ab over the shooters: shooter element i in a hands on f_i = sum_j in b F_ji A_j / A_i
// (reciprocity of the receiver-to-element form factors); F_ab is the area-weighted mean of f_i over
// a's shooters.
struct ObjectSums {
  std::vector<double> shooterArea;            // per object
  std::vector<std::size_t> shooters;          // per object
  std::vector<std::vector<double>> handedOn;  // [a][b]: sum over a's shooters of A_i f_i
  explicit ObjectSums(size_t objects)
      : shooterArea(objects, 0.0), shooters(objects, 0), handedOn(objects, std::vector<double>(objects, 0.0)) {}
  // Shooter element of area A in object a handing on perObject[b] = A f_b.
  void add(std::size_t a, double A, const std::vector<double>& perObject) {
    shooterArea[a] += A, ++shooters[a];
    for (std::size_t b = 0; b < perObject.size(); ++b) handedOn[a][b] += perObject[b];
  }
  double formFactor(std::size_t a, std::size_t b) const { return handedOn[a][b] / shooterArea[a]; }
};

// Shooter s's exact samples, added to the object sums.
template <class ObjectOf>
std::vector<PairSample> exactFromShooter(ExactReference& exact, std::size_t s, const ObjectOf& objectOf,
                                         const Atlas& atlas, ObjectSums& sums) {
  std::vector<PairSample> samples = exact.fromShooter(s);
  std::vector<double> perObject(sums.shooterArea.size(), 0.0);
  for (std::size_t t = 0; t < atlas.polygonOf.size(); ++t)
    if (samples[t].formFactor > 0) perObject[objectOf(t)] += samples[t].formFactor * atlas.positionArea[t].w;
  sums.add(objectOf(s), atlas.positionArea[s].w, perObject);
  return samples;
}

// One configuration's comparison, shooter by shooter.
struct LevelTally {
  ObjectSums sums;
  std::vector<double> relErrors, wholeErrors;  // every pair with F > 0; those seen whole
  std::size_t agree = 0;
  explicit LevelTally(size_t objects) : sums(objects) {}

  // Shooter s's GPU samples against the exact ones. Returns the form factor its visibility errors
  // add or remove, or -1 if it sees nothing (shooters inside closed solids, under a block, never shoot).
  template <class ObjectOf>
  double add(const std::vector<ProbeSample>& gpu, const std::vector<PairSample>& reference, std::size_t s,
             const ObjectOf& objectOf, const Atlas& atlas, LevelStats& st) {
    std::vector<double> perObject(sums.shooterArea.size(), 0.0);
    double misplaced = 0;
    bool seesAnything = false;
    for (std::size_t t = 0; t < gpu.size(); ++t) {
      const PairSample& ref = reference[t];
      if (gpu[t].formFactor > 0) perObject[objectOf(t)] += gpu[t].formFactor * atlas.positionArea[t].w;
      if (!ref.facing) continue;
      ++st.texelPairs;
      bool gv = gpu[t].visible > 0.5f;
      agree += gv == ref.visible;
      if (gv != ref.visible) misplaced += std::abs(double(gpu[t].formFactor) - ref.formFactor);
      seesAnything = seesAnything || ref.visible;
      st.falseVisible += gv && !ref.visible;
      st.falseHidden += !gv && ref.visible;
      if (ref.formFactor <= 0) continue;
      relErrors.push_back(std::abs(double(gpu[t].formFactor) - ref.formFactor) / ref.formFactor);
      if (ref.bound > 0)
        ++st.partlySeen;
      else
        wholeErrors.push_back(relErrors.back());
    }
    sums.add(objectOf(s), atlas.positionArea[s].w, perObject);
    return seesAnything ? misplaced : -1.0;
  }

  void finish(LevelStats& st) {
    st.visibilityAgreement = st.texelPairs ? double(agree) / double(st.texelPairs) : 1.0;
    st.ffRelErrorMedian = percentile(relErrors, 0.5);
    const double sum = std::accumulate(relErrors.begin(), relErrors.end(), 0.0);
    st.ffRelErrorMean = relErrors.empty() ? 0 : sum / double(relErrors.size());
    st.ffRelErrorP95 = percentile(relErrors, 0.95);
    st.ffRelErrorMax = relErrors.empty() ? 0 : *std::max_element(relErrors.begin(), relErrors.end());
    st.wholeRelErrorMedian = percentile(wholeErrors, 0.5);
    st.wholeRelErrorP95 = percentile(wholeErrors, 0.95);
    st.wholeRelErrorMax = wholeErrors.empty() ? 0 : *std::max_element(wholeErrors.begin(), wholeErrors.end());
  }
};

// A converged GPU solve (per-element shooting, the finest level asked for) against the dense one.
void compareSolution(const Scene& scene, const Atlas& atlas, const cpu::ExactVisibility& visibility,
                     const ValidateOptions& o, Validation& v) {
  DenseSolution dense = solveDense(scene, atlas, visibility);
  SolverState state(scene, atlas);
  ProgressiveSettings settings;
  settings.itemSubdivision = *std::max_element(o.levels.begin(), o.levels.end());
  settings.itemResolution = o.itemResolutions.front();
  settings.projection = o.projections.front();
  settings.shootLevel = 0;
  settings.stop.targetConvergence = o.solutionConvergence;
  ProgressiveSolver solver(state, settings);
  SolveStatus status;
  while (!status.done) status = solver.advance(256);
  v.solutionShots = status.shots;
  std::vector<glm::vec4> B = state.readRadiosity();
  std::vector<SolutionError> errors(scene.objects.size());
  std::vector<double> area(scene.objects.size(), 0.0);
  for (std::size_t t = 0; t < B.size(); ++t) {
    if (atlas.polygonOf[t] == kNoPolygon) continue;
    size_t obj = size_t(scene.polygons()[atlas.polygonOf[t]].object);
    double A = atlas.positionArea[t].w, d = luminance(dense.B[t]), g = luminance(glm::dvec3(B[t]));
    SolutionError& e = errors[obj];
    area[obj] += A;
    e.meanDense += d * A;
    e.meanGpu += g * A;
    e.rmse += (g - d) * (g - d) * A;
    e.maxError = std::max(e.maxError, std::abs(g - d));
  }
  for (size_t i = 0; i < errors.size(); ++i) {
    errors[i].object = scene.objects[i].name;
    if (area[i] <= 0) continue;
    errors[i].meanDense /= area[i];
    errors[i].meanGpu /= area[i];
    errors[i].rmse = std::sqrt(errors[i].rmse / area[i]);
  }
  v.solution = errors;
}

// Every pair of objects the reference's shooters reach from: reference and GPU F over them.
std::vector<ObjectFormFactor> objectFormFactors(const Scene& scene, const Atlas& atlas, const ObjectSums& exact,
                                                const ObjectSums& gpu) {
  std::vector<std::size_t> population(scene.objects.size(), 0);
  for (std::size_t t : chooseShooters(atlas, std::nullopt))
    ++population[std::size_t(scene.polygons()[atlas.polygonOf[t]].object)];
  std::vector<ObjectFormFactor> out;
  for (size_t a = 0; a < scene.objects.size(); ++a)
    for (size_t b = 0; b < scene.objects.size(); ++b)
      if (exact.shooterArea[a] > 0)
        out.push_back({scene.objects[a].name, scene.objects[b].name, exact.formFactor(a, b), exact.shooters[a],
                       population[a], gpu.formFactor(a, b)});
  return out;
}

}  // namespace

std::vector<std::size_t> chooseShooters(const Atlas& atlas, std::optional<std::size_t> count) {
  std::vector<std::size_t> elements;
  for (std::size_t t = 0; t < atlas.polygonOf.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon) elements.push_back(t);
  if (!count || *count >= elements.size()) return elements;
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < *count; ++i) chosen.push_back(elements[(2 * i + 1) * elements.size() / (2 * *count)]);
  return chosen;
}

Validation validate(const Scene& scene, const Atlas& atlas, const ValidateOptions& o) {
  Validation v;
  v.elements = atlas.elements;
  const std::vector<std::size_t> shooters = chooseShooters(atlas, o.shooters);
  v.shooters = shooters.size();
  const size_t objects = scene.objects.size();
  auto objectOf = [&](std::size_t t) { return scene.polygons()[atlas.polygonOf[t]].object; };

  // The exact side does not depend on L: once per shooter.
  auto t0 = std::chrono::steady_clock::now();
  ExactReference exact(scene, atlas);
  std::vector<std::vector<PairSample>> reference;
  ObjectSums exactSums(objects);
  for (std::size_t s : shooters) reference.push_back(exactFromShooter(exact, s, objectOf, atlas, exactSums));
  v.exactMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  SolverState state(scene, atlas);
  ObjectSums gpuSums(objects);
  double worstError = -1;
  std::size_t figureIndex = 0;  // into `shooters`
  for (Projection projection : o.projections)
    for (int asked : o.itemResolutions) {
      // auto: what a solve with this projection plans (kAutoItemResolution is no resolution).
      const int resolution = planShooting(scene, atlas, 0, asked, projection).itemResolution;
      for (int level : o.levels) {
        const bool first = v.levels.empty(),
                   figureConfig = projection == o.projections[0] && asked == o.itemResolutions[0];
        FormFactorProbe probe(state, level, resolution, projection);
        LevelStats st;
        st.projection = projection;
        st.itemResolution = resolution;
        st.itemSubdivision = level;
        st.itemTriangles = probe.itemTriangles();
        LevelTally tally(objects);
        for (std::size_t k = 0; k < shooters.size(); ++k) {
          const double misplaced =
              tally.add(probe.fromShooter(shooters[k]), reference[k], shooters[k], objectOf, atlas, st);
          if (first && misplaced > worstError) worstError = misplaced, figureIndex = k;
        }
        tally.finish(st);
        st.gpuMs = probe.gpuMilliseconds();
        v.levels.push_back(st);
        if (figureConfig && level == o.levels.back()) gpuSums = tally.sums;  // object F: first config, highest L
        // Figure samples: the chosen shooter at the first configuration's lowest and highest level.
        if (figureConfig && (level == o.levels.front() || level == o.levels.back())) {
          std::vector<ProbeSample> gpu = probe.fromShooter(shooters[figureIndex]);
          if (level == o.levels.front())
            v.figureGpu.assign(2, gpu);
          else
            v.figureGpu[1] = std::move(gpu);
        }
      }
    }
  if (o.visibility == Visibility::Bvh) {                              // the same pairs through the BVH's segment tests
    FormFactorProbe probe(state, 0, 16, Projection::Hemicube, true);  // (its item buffer is not drawn)
    LevelStats st;
    st.traced = true;
    LevelTally tally(objects);
    for (std::size_t k = 0; k < shooters.size(); ++k)
      tally.add(probe.fromShooter(shooters[k]), reference[k], shooters[k], objectOf, atlas, st);
    tally.finish(st);
    st.gpuMs = probe.gpuMilliseconds();
    v.levels.push_back(st);
  }
  v.figureShooter = shooters[figureIndex];
  v.figureExact = reference[figureIndex];
  if (o.solution) compareSolution(scene, atlas, exact.visibility(), o, v);
  v.objectFormFactors = objectFormFactors(scene, atlas, exactSums, gpuSums);
  return v;
}

std::string configName(const LevelStats& s) {
  if (s.traced) return "bvh (traced)";
  return fmt::format("{} {}^2", projectionName(s.projection), s.itemResolution);
}

int runValidate(const ValidateOptions& o) {
  if (!o.report.empty()) checkWritable(o.report, "--report");
  if (!o.figures.empty()) prepareFigureFolder(o.figures);
  parseFigureSize(o.figureSize);  // a bad size fails before the reference
  Scene scene = loadScene(o.scene, o.load);
  printWarnings(scene.warnings);
  if (scene.polygons().empty()) fail("{}: the scene has no faces with area", o.scene);
  Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  Atlas atlas = buildAtlas(scene, o.discretisation, backend->maxTextureSize());
  auto t0 = std::chrono::steady_clock::now();
  Validation v = validate(scene, atlas, o);
  double totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  fmt::print("{}: {} elements, {} shooters, exact reference {:.0f} ms, total {:.0f} ms\n\n", o.scene, v.elements,
             v.shooters, v.exactMs, totalMs);
  fmt::print("{}", levelTable(v));
  if (o.solution) {
    fmt::print("\nGPU solution ({} shots to convergence {}) against the dense exact solution, luminance of B:\n\n",
               v.solutionShots, o.solutionConvergence);
    fmt::print("| object | dense mean | GPU mean | RMSE | max error |\n|---|---|---|---|---|\n");
    for (const SolutionError& e : v.solution)
      fmt::print("| {} | {:.5g} | {:.5g} | {:.3g} | {:.3g} |\n", e.object, e.meanDense, e.meanGpu, e.rmse, e.maxError);
  }
  if (!o.report.empty()) {
    using nlohmann::json;
    json levels = json::array(), ffs = json::array();
    for (const LevelStats& s : v.levels)
      levels.push_back({{"visibility", s.traced ? "bvh" : "item-buffer"},
                        {"hemisphere", projectionName(s.projection)},
                        {"item_resolution", s.itemResolution},
                        {"item_subdivision", s.itemSubdivision},
                        {"item_triangles", s.itemTriangles},
                        {"texel_pairs", s.texelPairs},
                        {"visibility_agreement", s.visibilityAgreement},
                        {"false_visible", s.falseVisible},
                        {"false_hidden", s.falseHidden},
                        {"ff_rel_error_median", s.ffRelErrorMedian},
                        {"ff_rel_error_mean", s.ffRelErrorMean},
                        {"ff_rel_error_p95", s.ffRelErrorP95},
                        {"ff_rel_error_max", s.ffRelErrorMax},
                        {"partly_seen_pairs", s.partlySeen},
                        {"ff_rel_error_whole_median", s.wholeRelErrorMedian},
                        {"ff_rel_error_whole_p95", s.wholeRelErrorP95},
                        {"ff_rel_error_whole_max", s.wholeRelErrorMax},
                        {"gpu_ms", s.gpuMs}});
    for (const auto& f : v.objectFormFactors)
      ffs.push_back({{"from", f.from},
                     {"to", f.to},
                     {"reference", f.reference},
                     {"shooters", f.shooters},
                     {"elements", f.elements},
                     {"gpu", f.gpu}});
    json report = {{"scene", o.scene},
                   {"backend", backend->name()},
                   {"renderer", backend->renderer()},
                   {"elements", v.elements},
                   {"shooters", v.shooters},
                   {"exact_ms", v.exactMs},
                   {"total_ms", totalMs},
                   {"levels", levels},
                   {"object_form_factors", ffs},
                   {"provenance", provenanceJson(provenance(backend->name(), backend->renderer()))}};
    if (o.solution) {
      json sol = json::array();
      for (const SolutionError& e : v.solution)
        sol.push_back({{"object", e.object},
                       {"mean_dense", e.meanDense},
                       {"mean_gpu", e.meanGpu},
                       {"rmse", e.rmse},
                       {"max_error", e.maxError}});
      report["solution"] = {{"shots", v.solutionShots}, {"convergence", o.solutionConvergence}, {"objects", sol}};
    }
    writeTextFile(o.report, report.dump(2) + "\n");
  }
  if (!o.figures.empty()) {
    SolverState state(scene, atlas);
    writeFigures(o.figures, scene, atlas, state, camera, o, v, provenance(backend->name(), backend->renderer()));
  }
  return 0;
}

std::vector<std::vector<std::string>> levelRows(const Validation& v) {
  std::vector<std::vector<std::string>> rows = {
      {"item buffer", "L", "item triangles", "texel pairs", "visibility agreement", "false visible", "false hidden",
       "FF rel. error median", "mean", "p95", "max", "partly seen", "seen whole: median", "p95", "max", "GPU ms"}};
  for (const LevelStats& s : v.levels)
    rows.push_back({configName(s), fmt::format("{}", s.itemSubdivision), fmt::format("{}", s.itemTriangles),
                    fmt::format("{}", s.texelPairs), fmt::format("{:.5f}", s.visibilityAgreement),
                    fmt::format("{}", s.falseVisible), fmt::format("{}", s.falseHidden),
                    // significant digits: the errors span decades, and a fixed 4 decimals shows 0.0000
                    fmt::format("{:.3g}", s.ffRelErrorMedian), fmt::format("{:.3g}", s.ffRelErrorMean),
                    fmt::format("{:.3g}", s.ffRelErrorP95), fmt::format("{:.3g}", s.ffRelErrorMax),
                    fmt::format("{}", s.partlySeen), fmt::format("{:.3g}", s.wholeRelErrorMedian),
                    fmt::format("{:.3g}", s.wholeRelErrorP95), fmt::format("{:.3g}", s.wholeRelErrorMax),
                    fmt::format("{:.0f}", s.gpuMs)});
  return rows;
}

std::string levelTable(const Validation& v) {
  const std::vector<std::vector<std::string>> rows = levelRows(v);
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (const std::string& cell : rows[r]) out += "| " + cell + " ";
    out += "|\n";
    if (r == 0)
      for (std::size_t c = 0; c <= rows[r].size(); ++c) out += c == rows[r].size() ? "\n" : c == 0 ? "|---|" : "---|";
  }
  return out;
}

}  // namespace hemirad
