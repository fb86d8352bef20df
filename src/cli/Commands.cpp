#include "src/cli/Commands.h"

#include <fmt/format.h>

#include "src/base/DataDir.h"
#include "src/base/Error.h"
#include "src/options/CliDocs.h"
#include "src/options/Options.h"
#include "src/output/ImageFile.h"
#include "src/output/Provenance.h"
#include "src/solver/Projection.h"
#include "src/viewer/ViewerWorker.h"
#include "src/walk/ExperimentFlags.h"

namespace hemirad {

using options::add;
using options::addSwitch;

namespace {

void addScene(CLI::App* cmd, std::string& scene, LoadOptions& load, Discretisation& d) {
  cmd->add_option("scene", scene, "Wavefront OBJ (materials from its MTL) or glTF 2.0 (.gltf, .glb)")
      ->required()
      ->type_name("SCENE")
      // The README's scenes/cornell/cornell.obj from any folder: the shipped one (base/DataDir.h).
      ->transform(
          CLI::Validator([](std::string& path) { return path = findScene(path), std::string(); }, "", "shipped"))
      ->check(CLI::ExistingFile);
  add(cmd, "--emission", load.emission);
  CLI::Option* texelSize = add(cmd, "--texel-size", d.texelSize, "from --elements");
  add(cmd, "--elements", d.elements, std::to_string(Discretisation::kDefaultElements))->excludes(texelSize);
  add(cmd, "--chart-angle", d.chartAngle);
  add(cmd, "--uv", d.uv);
}

}  // namespace

Commands::Commands() {
  app.require_subcommand(1);
  app.set_version_flag("--version", versionString());
  addSolve();

  infoCmd = app.add_subcommand(
      "info", "Describe a scene: objects, polygons, area, emitters, elements, GPU and resident memory");
  addScene(infoCmd, info.scene, info.load, info.discretisation);
  add(infoCmd, "--item-subdiv", info.itemSubdivision, options::defaultText("--item-subdiv"));

  addValidate();
  benchCmd = app.add_subcommand("bench", "Time the solver: shots and time to convergence, per-pass split");
  addBenchFlags(benchCmd, bench);
  addView();
  addExperiment();
  addComparison();
  addAnimation();
  addVplError();
  addReference();
  addCompare();

  docsCmd = app.add_subcommand("docs", "Print docs/cli.md (this command line as markdown)")->group("");
  docsCmd->add_option("what", docs, "cli")->required()->check(CLI::IsMember({"cli"}));
}

void Commands::addSolve() {
  CLI::App* s = solveCmd = app.add_subcommand("solve", "Solve a scene and write images, atlas, mesh and report");
  addScene(s, solve.scene, solve.load, solve.discretisation);
  add(s, "--method", solve.methodName)->transform(options::oneOfNames(methods.names()));
  methods.declareFlags(s);  // each flag of every method, once
  add(s, "--backend", solve.backend.kind);
  add(s, "--gpu", solve.backend.gpu);
  addSwitch(s, "--gl-debug", solve.backend.debug);
  add(s, "--camera", solve.camera);
  add(s, "--width", solve.width);
  add(s, "--height", solve.height);
  add(s, "--supersample", supersample, "auto");
  add(s, "--image-plan", solve.imagePlan);
  add(s, "--msaa", solve.msaa, fmt::format("{}, or the backend's most if fewer", SolveOptions::kDefaultMsaa));
  add(s, "--exposure", solve.exposure);
  add(s, "--ambient", solve.ambient, "off; on for --camera-path frames");
  add(s, "--subdivide", solve.subdivide.adaptive);
  add(s, "--discontinuities", discontinuities, "auto");
  add(s, "--leaf-depth", solve.subdivide.maxDepth);
  add(s, "--split-gradient", solve.subdivide.rule.threshold);
  addSolveOutputs(s);
  addWalkthrough(s);
}

void Commands::addSolveOutputs(CLI::App* s) {
  for (auto [flag, path] : {std::pair{"--out", &solve.out},
                            {"--image", &solve.image},
                            {"--atlas", &solve.atlas},
                            {"--ply", &solve.ply},
                            {"--gltf", &solve.gltf},
                            {"--report", &solve.report}})
    add(s, flag, *path);
  CLI::Option* checkpoint = add(s, "--checkpoint", solve.checkpoint);
  add(s, "--checkpoint-every", solve.checkpointEvery)->needs(checkpoint);
  add(s, "--resume", solve.resume);
  addSwitch(s, "--quiet", quiet);
}

void Commands::addWalkthrough(CLI::App* s) {
  WalkthroughOptions& w = solve.walkthrough;
  CLI::Option* path = add(s, "--camera-path", solve.cameraPath);
  path->needs(add(s, "--frames", w.framesDir)->needs(path));
  add(s, "--fps", w.fps)->needs(path);
  CLI::Option* frameMs = add(s, "--frame-ms", w.frameMs)->needs(path);
  add(s, "--frame-shots", w.frameShots)->needs(path)->excludes(frameMs);
  add(s, "--reference-convergence", solve.referenceConvergence)->needs(path);
}

void Commands::addValidate() {
  CLI::App* v = validateCmd =
      app.add_subcommand("validate", "Check the GPU item buffer and form factors against the exact CPU reference");
  addScene(v, validate.scene, validate.load, validate.discretisation);
  add(v, "--levels", validate.levels);
  add(v, "--shooters", shooters);
  add(v, "--item-res", validate.itemResolutions);
  add(v, "--figures", validate.figures);
  add(v, "--figure-size", validate.figureSize);
  add(v, "--camera", validate.camera);
  add(v, "--hemisphere", validateProjections, "[orthographic]");
  add(v, "--backend", validate.backend.kind);
  add(v, "--gpu", validate.backend.gpu);
  add(v, "--report", validate.report);
  addSwitch(v, "--solution", validate.solution);
  add(v, "--visibility", validate.visibility, "item-buffer");
}

void Commands::addView() {
  CLI::App* w = viewCmd = app.add_subcommand("view", "Open a window showing the solution refine live (GLFW)");
  w->footer(std::string("Controls:\n") + viewerControls());
  addScene(w, view.scene, view.load, view.discretisation);
  ProgressiveSettings& p = view.progressive;
  add(w, "--algorithm", p.algorithm);
  add(w, "--backend", view.backend.kind);
  add(w, "--gpu", view.backend.gpu);
  add(w, "--camera", view.camera);
  add(w, "--width", view.width);
  add(w, "--height", view.height);
  add(w, "--exposure", view.exposure);
  add(w, "--ambient", view.ambient);
  CLI::Option* frameMs = add(w, "--frame-ms", view.frameMs);
  add(w, "--frame-shots", view.shotsPerFrame)->excludes(frameMs);
  add(w, "--frame-count", view.frames);
  add(w, "--screenshot", view.screenshot);
  options::addItemPlan(w, p);
  add(w, "--shooters-per-pass", p.shootersPerPass);
  add(w, "--converge", p.stop.targetConvergence);
  add(w, "--shots", p.stop.maxShots);
  add(w, "--method", view.method)->transform(options::oneOfNames(viewerMethods()));
  InstantSettings& i = view.instant;
  i.seed = 1;             // as solve's
  i.itemSubdivision = 3;  // as solve's (src/method/instant): hemispherical shadow maps, curved edges
  viewInstantOnly = {add(w, "--vpls", i.vpls),         add(w, "--vpl-bounces", i.bounces),
                     add(w, "--vpl-clamp", i.clamp),   add(w, "--shadow-res", i.shadowResolution),
                     add(w, "--shading", viewShading), add(w, "--interleave", i.interleave),
                     add(w, "--seed", i.seed)};
}

// view runs progressive refinement (and its algorithms) or instant radiosity, whose flags it
// refuses with the other.
int Commands::runView() {
  if (view.method != "instant")
    for (const CLI::Option* o : viewInstantOnly)
      if (*o) throw InputError(o->get_name() + " is for --method instant");
  // Instant radiosity's shadow maps are hemispherical (curved edges): they keep their own item-mesh
  // level unless --item-subdiv says otherwise, not the default preset's 0.
  if (*viewCmd->get_option("--item-subdiv")) view.instant.itemSubdivision = view.progressive.itemSubdivision;
  view.progressive.projection = options::oneProjection(int(view.progressive.projection));  // refuses `all`
  view.shading = viewShading == "forward" ? Shading::Forward : Shading::Deferred;
  return hemirad::runView(view);
}

void Commands::addExperiment() {
  CLI::App* x = experimentCmd =
      app.add_subcommand("experiment",
                         "Seed 004's experiments: progressive vs importance vs perspective along camera paths; or, "
                         "with SPEC, a parameter sweep run here or on Slurm (docs/sweeps.md)");
  seed004Only = addExperimentFlags(x, experiment);
  seed004Only.push_back(addSwitch(x, "--keep-frames", experiment.frames));
  addSweep(x);
}

void Commands::addSweep(CLI::App* x) {
  x->add_option("spec", sweep.spec, "A sweep spec (JSON, docs/sweeps.md); without it, seed 004's experiments")
      ->type_name("SPEC")
      ->check(CLI::ExistingFile);
  add(x, "--slurm", sweep.slurm);
  add(x, "--jobs", sweep.jobs);
  mergeCmd = x->add_subcommand("merge",
                               "Collect a sweep's task reports into DIR/results.csv and results.md; "
                               "lists missing and failed configurations");
  mergeCmd->add_option("dir", sweep.dir, "The sweep's folder")
      ->required()
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
  runTaskCmd = x->add_subcommand("run-task",
                                 "Run one configuration of a sweep (what each Slurm array task runs); "
                                 "resumes from its checkpoint");
  runTaskCmd->add_option("dir", sweep.dir, "The sweep's folder")
      ->required()
      ->type_name("DIR")
      ->check(CLI::ExistingDirectory);
  runTaskCmd->add_option("index", sweep.index, "The configuration, 0 to N - 1 ($SLURM_ARRAY_TASK_ID)")
      ->required()
      ->type_name("INDEX");
}

void Commands::addComparison() {
  CLI::App* c = comparisonCmd = app.add_subcommand(
      "compare-methods", "Error against solver time: progressive refinement vs stochastic iteration, same run");
  MethodComparisonOptions& m = comparison;
  add(c, "--scenes", m.scenes);
  add(c, "--elements", m.elements);
  add(c, "--reference-convergence", m.referenceConvergence);
  add(c, "--shots", m.iterations, "1024 (stochastic iterations; progressive gets as much solver time)");
  add(c, "--shooters-per-pass", m.progressive.shootersPerPass);
  options::addItemPlan(c, m.progressive, false);  // the shooters are one texel each (shoot level 0)
  add(c, "--seed", m.seed);
  add(c, "--out-dir", m.out);
  add(c, "--figure-size", m.figureSize);
  add(c, "--backend", m.backend.kind);
  add(c, "--gpu", m.backend.gpu);
}

void Commands::addAnimation() {
  CLI::App* a = animateCmd =
      app.add_subcommand("animate",
                         "Stochastic iteration under moving lights: frames along a light path, each compared with a "
                         "converged progressive solve");
  AnimationOptions& m = animation;
  m.stochastic.window = 64;
  addScene(a, m.scene, m.load, m.discretisation);
  add(a, "--light-path", m.lightPath)->required();
  add(a, "--frames", m.framesDir)->required();
  add(a, "--fps", m.fps);
  add(a, "--frame-shots", m.frameIterations, "32 (stochastic iterations per frame)");
  add(a, "--window", m.stochastic.window);
  add(a, "--seed", m.stochastic.seed);
  add(a, "--shooters-per-pass", m.stochastic.shooters);
  add(a, "--item-res", m.stochastic.itemResolution);
  add(a, "--item-subdiv", m.stochastic.itemSubdivision);
  add(a, "--reference-convergence", m.referenceConvergence);
  add(a, "--camera", m.camera);
  add(a, "--width", m.width);
  add(a, "--height", m.height);
  add(a, "--backend", m.backend.kind);
  add(a, "--gpu", m.backend.gpu);
}

void Commands::addVplError() {
  CLI::App* c = vplErrorCmd = app.add_subcommand(
      "compare-vpls",
      "Instant radiosity's image error per region against a converged progressive solve, per VPL count");
  VplErrorOptions& v = vplError;
  addScene(c, v.scene, v.load, v.discretisation);
  add(c, "--vpls", v.vpls, "64,128,...,4096 (a row each)");
  add(c, "--vpl-bounces", v.instant.bounces);
  add(c, "--vpl-clamp", v.instant.clamp);
  add(c, "--shadow-res", v.instant.shadowResolution);
  add(c, "--item-subdiv", v.instant.itemSubdivision);
  add(c, "--seed", v.instant.seed);
  add(c, "--reference-convergence", v.referenceConvergence);
  add(c, "--camera", v.camera);
  add(c, "--width", v.width);
  add(c, "--height", v.height);
  add(c, "--out-dir", v.out);
  add(c, "--figure-size", v.figureSize);
  add(c, "--image", v.sideBySide);  // instant (the largest VPL count) | progressive, side by side
  add(c, "--backend", v.backend.kind);
  add(c, "--gpu", v.backend.gpu);
}

void Commands::addReference() {
  CLI::App* r = referenceCmd = app.add_subcommand(
      "reference",
      "Path-trace the camera view unbiased, in B units as solve's --out, with per-pixel standard errors "
      "from independent batches (docs/reference.md)");
  addReferenceFlags(r, reference, imageFileWriters());
}

void Commands::addCompare() {
  CLI::App* c = compareCmd = app.add_subcommand(
      "compare",
      "Relative luminance error of image A against image B (the reference) over surface interiors, edge "
      "and corner bands, the surfaces beside a light, each object, and an error map (docs/reference.md)");
  CompareOptions& o = compare;
  c->add_option("a", o.a, "The image judged (.exr)")->required()->type_name("A")->check(CLI::ExistingFile);
  c->add_option("b", o.b, "The reference (.exr)")->required()->type_name("B")->check(CLI::ExistingFile);
  add(c, "--scene", o.scene)->required();
  add(c, "--emission", o.load.emission);
  add(c, "--camera", o.camera);
  add(c, "--stderr", o.standardError)->check(CLI::ExistingFile);
  add(c, "--error-map", o.errorMap);
  add(c, "--error-range", o.errorRange);
  add(c, "--markdown", o.markdownOut);
}

// The chosen method with its own flags bound and checked.
void Commands::settle() {
  if (!*solveCmd) return;
  MethodUnit& method = methods.choose(solve.methodName, *solveCmd);
  solve.gpu = !gl::rendersOnCpu(solve.backend);
  method.settle(solve);
  solve.method = &method;
  // The auto ones follow the method's choice of an exact camera image; the user's word stands.
  const bool exact = method.exactImages();
  if (solve.imagePlan == ImagePlan::Exact && !exact)
    throw InputError(
        fmt::format("--image-plan exact takes per-pixel direct light and the near final gather, "
                    "progressive refinement's, not {}'s",
                    method.name()));
  solve.discontinuities =
      discontinuities == "auto" ? exact && solve.discretisation.uv != UvSource::Input : discontinuities == "contact";
  solve.supersample = supersample != kAutoSupersample ? supersample
                      : exact                         ? kExactImagesSupersample
                                                      : kDefaultSupersample;
  solve.progress = !quiet;
}

int Commands::runSolve() {
  settle();
  return hemirad::runSolve(solve);
}

int Commands::runExperiment() {
  if (*mergeCmd) return runSweepMergeCommand(sweep);
  if (*runTaskCmd) return runSweepTaskCommand(sweep);
  const CLI::Option* slurm = experimentCmd->get_option("--slurm");
  const CLI::Option* jobs = experimentCmd->get_option("--jobs");
  if (sweep.spec.empty()) {
    for (const CLI::Option* o : {slurm, jobs})
      if (*o)
        throw InputError(o->get_name() + " needs a sweep SPEC: hemirad experiment SPEC " + o->get_name() + " ...");
    experiment.walkthrough.writeFrame = writePng;
    return hemirad::runExperiment(experiment);
  }
  for (const CLI::Option* o : seed004Only)
    if (*o)
      throw InputError(o->get_name() + " is for seed 004's experiments, not a SPEC sweep (the spec sets the flags)");
  if (*experimentCmd->get_option("--out-dir")) sweep.outDir = experiment.out;
  if (*jobs && *slurm) throw InputError("--jobs is for a local run (--out-dir), not --slurm");
  return runSweepCommand(sweep);
}

int Commands::run() {
  if (*solveCmd) return runSolve();
  if (*infoCmd) return runInfo(info);
  if (*benchCmd) return runBench(bench);
  if (*viewCmd) return runView();
  if (*experimentCmd) return runExperiment();
  if (*comparisonCmd) {
    comparison.progressive.projection = options::oneProjection(int(comparison.progressive.projection));
    return runMethodComparison(comparison);
  }
  if (*vplErrorCmd) return runVplError(vplError);
  if (*referenceCmd) return runReference(reference, imageFileWriters());
  if (*compareCmd) return runCompare(compare);
  if (*animateCmd) {
    animation.stochastic.timings = gl::TimerMode::Off;
    return runAnimation(animation);
  }
  if (*docsCmd) {
    fmt::print("{}", options::markdown(app));
    return 0;
  }
  validate.projections.clear();
  for (int p : validateProjections) {
    if (p != options::kAllProjections)
      validate.projections.push_back(Projection(p));
    else
      for (Projection each : allProjections()) validate.projections.push_back(each);
  }
  validate.shooters = shooters == "all" ? std::nullopt : std::optional<std::size_t>(std::stoul(shooters));
  return runValidate(validate);
}

}  // namespace hemirad
