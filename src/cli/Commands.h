// The subcommands of `hemirad` and the flags each takes from the option table (Options.h).
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "src/bench/Bench.h"
#include "src/cli/Solve.h"
#include "src/cli/SweepCommand.h"
#include "src/method/MethodChoice.h"
#include "src/reference/ReferenceCommand.h"
#include "src/validate/Validate.h"
#include "src/viewer/Viewer.h"
#include "src/walk/Experiment.h"
#include "src/walk/LightAnimation.h"
#include "src/walk/MethodComparison.h"
#include "src/walk/VplError.h"

namespace hemirad {

// Built in place (the parser holds pointers into the options): parse `app`, then run().
struct Commands {
  Commands();
  Commands(const Commands&) = delete;
  // Runs the chosen subcommand, after settling what depends on several flags. Throws InputError.
  int run();
  // Settles what depends on several of solve's flags (InputError for a bad combination), as
  // run() does before solving: a sweep's configurations are checked so before any runs.
  void settle();

  CLI::App app{"hemirad: diffuse global illumination by GPU progressive-refinement radiosity", "hemirad"};
  SolveOptions solve;
  InfoOptions info;
  ValidateOptions validate;
  BenchOptions bench;
  ViewerOptions view;
  ExperimentOptions experiment;
  MethodComparisonOptions comparison;
  AnimationOptions animation;
  VplErrorOptions vplError;
  SweepCommandOptions sweep;
  ReferenceOptions reference;
  CompareOptions compare;

 private:
  void addSolve();
  void addSolveOutputs(CLI::App* s);
  void addWalkthrough(CLI::App* s);
  void addValidate();
  void addView();
  int runView();
  void addExperiment();
  void addSweep(CLI::App* x);
  int runExperiment();
  void addComparison();
  void addAnimation();
  void addVplError();
  void addReference();
  void addCompare();
  int runSolve();

  // Flags read into text, turned into the options after parsing.
  std::string viewShading = "deferred", shooters = "16";
  std::vector<int> validateProjections{0};  // Projections, or options::kAllProjections
  // solve's --discontinuities and --supersample, auto resolved in settle() (docs/solve.md#exact-images).
  std::string discontinuities = "auto";
  int supersample = kAutoSupersample;
  bool quiet = false;
  std::string docs;
  CLI::App *solveCmd = nullptr, *infoCmd = nullptr, *validateCmd = nullptr, *benchCmd = nullptr, *viewCmd = nullptr,
           *experimentCmd = nullptr, *docsCmd = nullptr, *comparisonCmd = nullptr, *animateCmd = nullptr,
           *vplErrorCmd = nullptr, *mergeCmd = nullptr, *runTaskCmd = nullptr, *referenceCmd = nullptr,
           *compareCmd = nullptr;
  MethodChoice methods;                       // solve's --method, each with its own flags
  std::vector<CLI::Option*> viewInstantOnly;  // flags view takes for --method instant only
  std::vector<CLI::Option*> seed004Only;      // experiment's flags that mean nothing to a SPEC sweep
};

}  // namespace hemirad
