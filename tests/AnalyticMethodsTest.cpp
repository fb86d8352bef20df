// Issue 31: every method passes the analytic cases, each within a tolerance from its own standard
// error: Howell's parallel and perpendicular unit squares (receiver B = rho E F exactly) and the
// blocked squares (a half-size grey blocker between the parallel ones, against element-by-element
// shooting at the same elements: binary visibility per element pair is the discretisation's, not a
// method's). The closed box is the contract test's (tests/MethodContractTest.cpp). Stochastic
// iteration once landed 2.3-2.6 % low on the blocked squares while progressive refinement was
// within 0.3 %; now each seed-to-seed spread bounds its method's mean.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "src/method/Registry.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// Per registered method: flags that solve the unit squares at ~300 elements quickly, and how many
// seeds estimate its standard error (1: deterministic). Instant radiosity shades camera pixels
// only (no per-element B to compare); its closed box is the contract test's.
struct MethodRuns {
  std::string flags;
  int seeds = 1;
};
const std::map<std::string, MethodRuns> kRuns = {
    {"progressive", {"--converge 0.9999", 1}},
    {"stochastic", {"--method stochastic --shots 128 --item-res 128 --item-subdiv 1", 8}},
    {"instant", {"", 0}},
};

double receiverB(const std::string& scene, const std::string& flags) {
  return test::solvedObjectB(test::sourcePath("scenes/analytic/" + scene) + " --elements 300 " + flags, "receiver");
}

}  // namespace

TEST_CASE(
    "Every method solves the parallel, perpendicular and blocked unit squares within three of its standard errors",
    "[heavy][gl][analytic]") {
  const std::string name = GENERATE(from_range(methodNames()));
  REQUIRE(kRuns.count(name) == 1);  // a new method declares its runs here
  const MethodRuns& runs = kRuns.at(name);
  if (runs.seeds == 0) return;
  const double blocked = receiverB("blocked_squares.obj", "--preset reference --item-res 256 --converge 0.9999");
  struct Case {
    const char* scene;
    double expected;
  };
  for (const Case c : {Case{"parallel_squares.obj", 0.5 * 0.19982}, Case{"perpendicular_squares.obj", 0.5 * 0.20004},
                       Case{"blocked_squares.obj", blocked}}) {
    double sum = 0, squares = 0;
    for (int seed = 1; seed <= runs.seeds; ++seed) {
      const double b = receiverB(c.scene, runs.flags + (runs.seeds > 1 ? " --seed " + std::to_string(seed) : ""));
      sum += b, squares += b * b;
    }
    const double mean = sum / runs.seeds;
    const double se =
        runs.seeds > 1 ? std::sqrt(std::max(0.0, squares / runs.seeds - mean * mean) / (runs.seeds - 1)) : 0.0;
    // Three standard errors, and 0.3 % for what every method shares at 300 elements: each element's
    // form factor taken at its centre (exact per point), its unshot remainder (1e-4).
    const double tolerance = 3 * se + 0.003 * c.expected;
    INFO("--method " << name << ", " << c.scene << ": receiver B " << mean << " (standard error " << se << ", "
                     << runs.seeds << " seeds), expected " << c.expected << " within " << tolerance);
    CHECK(std::abs(mean - c.expected) <= tolerance);
    CHECK(se <= 0.02 * c.expected);  // a spread this wide would make the test unable to fail
  }
}
