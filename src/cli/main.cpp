// hemirad: GPU progressive-refinement radiosity with a hemispherical item buffer.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>

#include "gl/Backend.h"
#include "src/cli/AmbientFlag.h"
#include "src/base/Error.h"
#include "src/bench/Bench.h"
#include "src/solver/Control.h"
#include "src/cli/Solve.h"
#include "src/validate/Validate.h"
#include "src/walk/Experiment.h"
#include "src/viewer/Viewer.h"

using namespace hemirad;

namespace {

void addSceneFlags(CLI::App* cmd, std::string& scene, LoadOptions& load, Discretisation& d) {
  cmd->add_option("scene", scene, "Wavefront OBJ (materials from its MTL)")->required()->check(CLI::ExistingFile);
  static const std::map<std::string, EmissionSource> emission{{"ke", EmissionSource::Ke}, {"ka", EmissionSource::Ka}};
  cmd->add_option("--emission", load.emission, "MTL key that gives emission: ke (default) or ka (the thesis)")
      ->transform(CLI::CheckedTransformer(emission, CLI::ignore_case));
  auto* ts = cmd->add_option("--texel-size", d.texelSize, "Element (texel) side in scene units")
                 ->check(CLI::Validator(
                     [](std::string& v) {
                       char* end = nullptr;
                       double x = std::strtod(v.c_str(), &end);
                       return end != v.c_str() && *end == '\0' && x > 0 && std::isfinite(x)
                                  ? std::string()
                                  : "must be a positive number of scene units, not '" + v + "'";
                     },
                     "SIZE > 0"));
  cmd->add_option("--elements", d.elements, "Choose the texel size for about N elements (default 10000)")
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 28))
      ->excludes(ts);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hemirad: diffuse global illumination by GPU progressive-refinement radiosity"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "hemirad 0.1.0");

  SolveOptions solve;
  std::string backend = "osmesa";
  CLI::App* s = app.add_subcommand("solve", "Solve a scene and write images, atlas, mesh and report");
  addSceneFlags(s, solve.scene, solve.load, solve.discretisation);
  auto& pr = solve.progressive;
  auto* converge = s->add_option("--converge", pr.stop.targetConvergence,
                                 "Stop at this convergence, 1 - unshot/emitted power (default 0.9)")
                       ->check(CLI::Range(0.0, 1.0).description("in (0, 1)"))
                       ->check([](const std::string& v) { return std::stod(v) > 0 && std::stod(v) < 1 ? "" : "must be in (0, 1)"; });
  auto* shots = s->add_option("--shots", pr.stop.maxShots, "Stop after N shots")->check(CLI::Range(1u, 1u << 30));
  s->add_option("--item-subdiv", pr.itemSubdivision, "Item-mesh 1-to-4 subdivision level L (default 3)")
      ->check(CLI::Range(0, 8));
  s->add_option("--item-res", pr.itemResolution, "Item buffer resolution in pixels (default 512)")
      ->check(CLI::Range(16, 16384));
  std::string solveProjection = "stereographic";
  s->add_option("--hemisphere", solveProjection, "Item buffer: stereographic (seed 003, default) or hemicube")
      ->check(CLI::IsMember({"stereographic", "hemicube"}));
  s->add_option("--shoot-level", pr.shootLevel, "Substructuring: shoot from 2^k x 2^k texel blocks (default 1)")
      ->check(CLI::Range(0, 8));
  s->add_option_function<std::string>(
       "--algorithm", [&pr](const std::string& a) { pr.algorithm = parseAlgorithm(a); },
       "progressive (default); importance: shooters ranked by unshot power x importance from the camera; "
       "perspective: importance-driven, and only what the view sees receives (seed 004)")
      ->check(CLI::IsMember(algorithmNames()));
  s->add_option("--fov-decay", pr.fovDecayShots,
                "Perspective-driven: shots over which the simulated field of view grows from the camera's to the "
                "whole scene after each camera move (default: a quarter of the shooter blocks)")
      ->check(CLI::Range(1u, 1u << 30));
  s->add_option("--shooters-per-pass", pr.shootersPerPass,
                fmt::format("Seed 003's batching: the K best blocks shoot in one pass (default 16, at most {})",
                            kMaxPassShooters))
      ->check(CLI::Range(1, int(kMaxPassShooters)));
  s->add_flag_callback(
      "--sync-timings", [&pr] { pr.timings = gl::TimerMode::Synchronous; },
      "Exact per-pass times: wait for the GPU at every pass end (slower; needed on llvmpipe)");
  s->add_option("--backend", backend, "GL backend: osmesa (default), egl, auto")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}));
  s->add_option("--gpu", solve.backend.gpu, "EGL device index")->check(CLI::Range(0, 1023));
  s->add_flag("--gl-debug", solve.backend.debug, "Report GL errors through KHR_debug");
  s->add_option("--camera", solve.camera, "eye=x,y,z,target=x,y,z,up=x,y,z,fov=degrees (default: SCENE.camera)");
  s->add_option("--width", solve.width, "Image width (default 512)")->check(CLI::Range(1, 16384));
  s->add_option("--height", solve.height, "Image height (default 512)")->check(CLI::Range(1, 16384));
  s->add_option("--supersample", solve.supersample, "Samples per pixel side (default 2)")->check(CLI::Range(1, 8));
  s->add_option("--exposure", solve.exposure, "PNG/PLY exposure in stops over the automatic one (default 0)");
  addAmbientFlag(s, solve.ambient);
  s->add_option("--out", solve.out, "Linear camera render (.exr)");
  s->add_option("--image", solve.image, "Tone-mapped camera render (.png)");
  s->add_option("--atlas", solve.atlas, "Radiosity atlas, one texel per element (.exr)");
  s->add_option("--ply", solve.ply, "Mesh with per-vertex radiosity (.ply)");
  s->add_option("--report", solve.report, "Report (.json)");
  auto* checkpoint = s->add_option("--checkpoint", solve.checkpoint,
                                   "Write the solve's state here (atomically) at the end, on SIGINT/SIGTERM and every "
                                   "--checkpoint-every shots");
  s->add_option("--checkpoint-every", solve.checkpointEvery, "Also checkpoint every N shots")
      ->check(CLI::Range(1u, 1u << 30))
      ->needs(checkpoint);
  s->add_option("--resume", solve.resume, "Continue from a checkpoint of the same scene and parameters")
      ->check(CLI::ExistingFile);
  bool quiet = false;
  s->add_flag("--quiet", quiet, "No progress bar");
  auto* path = s->add_option("--camera-path", solve.cameraPath,
                             "Walkthrough: keyframes 'TIME eye=.. target=.. fov=..' per line (README: Walkthroughs); "
                             "writes a frame per 1/--fps s and frames.csv into --frames")
                   ->check(CLI::ExistingFile);
  auto* frames = s->add_option("--frames", solve.walkthrough.framesDir, "Folder for the walkthrough's frames and frames.csv")
                     ->needs(path);
  path->needs(frames);
  auto& wk = solve.walkthrough;
  s->add_option("--fps", wk.fps, "Walkthrough frames per second of path time (default 10)")
      ->check(CLI::Range(0.01, 1000.0))
      ->needs(path);
  auto* frameMs = s->add_option("--frame-ms", wk.frameMs, "Solver milliseconds per walkthrough frame (default 100)")
                      ->check(CLI::Range(0.0, 1e7))
                      ->needs(path);
  s->add_option("--frame-shots", wk.frameShots, "Instead of --frame-ms: shots per frame (reproducible; whole passes of --shooters-per-pass)")
      ->check(CLI::Range(1u, 1u << 20))
      ->needs(path)
      ->excludes(frameMs);
  s->add_option("--reference-convergence", solve.referenceConvergence,
                "Convergence of the reference the frames are compared with (default 0.99)")
      ->check(CLI::Range(0.5, 0.99999))
      ->needs(path);

  InfoOptions info;
  CLI::App* i = app.add_subcommand("info", "Describe a scene: objects, polygons, area, emitters, elements");
  addSceneFlags(i, info.scene, info.load, info.discretisation);
  i->add_option("--item-subdiv", info.itemSubdivision, "Item-mesh subdivision level to count (default 3)")
      ->check(CLI::Range(0, 8));

  ValidateOptions validate;
  std::string validateBackend = "osmesa", shooters = "16";
  CLI::App* v = app.add_subcommand("validate", "Check the GPU item buffer and form factors against the exact CPU reference");
  addSceneFlags(v, validate.scene, validate.load, validate.discretisation);
  v->add_option("--levels", validate.levels, "Item-mesh subdivision levels to compare (default 0,1,2,3,4)")
      ->delimiter(',')
      ->check(CLI::Range(0, 8));
  v->add_option("--shooters", shooters, "Shooter elements: a count spread over the scene, or 'all' (default 16)")
      ->check([](const std::string& s) {
        if (s == "all") return std::string();
        try {
          return std::stoul(s) > 0 && s.find_first_not_of("0123456789") == std::string::npos ? std::string()
                                                                                              : "must be a count or 'all'";
        } catch (...) {
          return std::string("must be a count or 'all'");
        }
      });
  v->add_option("--item-res", validate.itemResolutions, "Item buffer resolutions (pixel budget side; default 512)")
      ->delimiter(',')
      ->check(CLI::Range(16, 16384));
  v->add_option("--figures", validate.figures, "Write plots, CSV, heat maps and index.html into this folder");
  v->add_option("--camera", validate.camera, "Camera of the view figures (default: SCENE.camera)");
  std::vector<std::string> validateProjections{"stereographic"};
  v->add_option("--hemisphere", validateProjections,
                "Item buffers to compare: stereographic (seed 003), hemicube, or both (equal pixel budgets)")
      ->delimiter(',')
      ->check(CLI::IsMember({"stereographic", "hemicube"}));
  v->add_option("--backend", validateBackend, "GL backend: osmesa (default), egl, auto")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}));
  v->add_option("--report", validate.report, "Report (.json)");
  v->add_flag("--solution", validate.solution,
              "Also compare a converged GPU solution with the dense exact one (up to 5,000 elements)");

  BenchOptions bench;
  CLI::App* b = app.add_subcommand("bench", "Time the solver: shots and time to convergence, per-pass split");
  addBenchFlags(b, bench);

  ViewerOptions view;
  CLI::App* w = app.add_subcommand("view", "Open a window showing the solution refine live (GLFW)");
  addSceneFlags(w, view.scene, view.load, view.discretisation);
  addViewFlags(w, view);

  ExperimentOptions experiment;
  CLI::App* x = app.add_subcommand("experiment",
                                   "Seed 004's experiments: progressive vs importance vs perspective along camera paths");
  addExperimentFlags(x, experiment);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitInputError;
  }
  (void)converge;
  try {
    if (*s) {
      // A walkthrough shoots until its path ends; a single solve stops at 0.9 unless told.
      if (!*shots && !*converge) pr.stop.targetConvergence = solve.cameraPath.empty() ? 0.9 : 0.9999;
      solve.backend.kind = gl::parseBackendKind(backend);
      pr.projection = parseProjection(solveProjection);
      solve.progress = !quiet;
      return runSolve(solve);
    }
    if (*b) return runBench(bench);
    if (*w) return runView(view);
    if (*x) return runExperiment(experiment);
    if (*v) {
      validate.backend.kind = gl::parseBackendKind(validateBackend);
      validate.projections.clear();
      for (const auto& p : validateProjections) validate.projections.push_back(parseProjection(p));
      validate.shooters = shooters == "all" ? std::nullopt : std::optional<std::size_t>(std::stoul(shooters));
      return runValidate(validate);
    }
    return runInfo(info);
  } catch (const InputError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return kExitFailure;
  }
}
