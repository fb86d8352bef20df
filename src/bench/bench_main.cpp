// hemirad-bench: `hemirad bench` alone, linked without image, mesh-export or CGAL libraries, so it
// runs on GPU machines that have no package registry (ci/gpu-bundle carries it).
#include <CLI/CLI.hpp>
#include <cstdio>

#include "src/bench/Bench.h"
#include "src/base/Error.h"
#include "src/cli/Suggest.h"
#include "src/output/Provenance.h"

int main(int argc, char** argv) {
  hemirad::recordCommandLine(argc, argv);  // the JSON's provenance
  CLI::App app{"hemirad-bench: time the progressive radiosity solver", "hemirad-bench"};
  hemirad::BenchOptions options;
  hemirad::addBenchFlags(&app, options);
  if (std::optional<int> exit = hemirad::options::parse(app, argc, argv)) return *exit;
  try {
    return hemirad::runBench(options);
  } catch (const hemirad::InputError& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return hemirad::kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hemirad: error: %s\n", e.what());
    return hemirad::kExitFailure;
  }
}
