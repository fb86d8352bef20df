// hemirad-bench: `hemirad bench` alone, linked without image, mesh-export or CGAL libraries, so it
// runs on GPU machines that have no package registry (ci/gpu-bundle carries it). Its
// `experiment` subcommand is `hemirad experiment` (seed 004's walkthroughs) without figures or
// frame PNGs: the CSVs and the summary, to time the three algorithms on such a machine; its
// `reference` subcommand is `hemirad reference` writing PFM (oiiotool converts it to EXR).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "src/base/Error.h"
#include "src/bench/Bench.h"
#include "src/options/Suggest.h"
#include "src/output/Pfm.h"
#include "src/output/Provenance.h"
#include "src/reference/ReferenceRun.h"
#include "src/walk/ExperimentFlags.h"

int main(int argc, char** argv) {
  hemirad::recordCommandLine(argc, argv);  // the JSON's provenance
  CLI::App app{"hemirad-bench: time the progressive radiosity solver", "hemirad-bench"};
  hemirad::BenchOptions options;
  hemirad::addBenchFlags(&app, options);
  hemirad::ExperimentOptions experiment;
  experiment.figures = false;  // matplotlib is not carried to GPU machines
  CLI::App* x =
      app.add_subcommand("experiment", "Seed 004's experiments (as hemirad experiment): CSVs and summary, no figures");
  hemirad::addExperimentFlags(x, experiment);
  hemirad::ReferenceOptions reference;
  const hemirad::ReferenceWriters pfm{
      {".pfm"},
      {".pfm"},
      {},
      [](const std::string&, const hemirad::Image& i, double) { return hemirad::encodePfm(i); },
      hemirad::encodePfm};
  CLI::App* r = app.add_subcommand("reference", "The path-traced reference (as hemirad reference), written as PFM");
  hemirad::addReferenceFlags(r, reference, pfm);
  if (std::optional<int> exit = hemirad::options::parse(app, argc, argv)) return *exit;
  try {
    if (*r) return hemirad::runReference(reference, pfm);
    return *x ? hemirad::runExperiment(experiment) : hemirad::runBench(options);
  } catch (const hemirad::InputError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return hemirad::kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return hemirad::kExitFailure;
  }
}
