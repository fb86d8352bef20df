// The progress bar's ETA (src/output/Eta.h) on recorded convergence histories (tests/data/): from
// 10 % of the shots on, the shots it predicts are left are within 2x of those really left; the
// bar line fits the terminal's width.
#include <catch2/catch.hpp>
#include <cmath>

#include "src/output/Eta.h"
#include "src/output/Progress.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// The recorded runs (tests/data/): convergence after each pass, as (shots, convergence).
const char* const kRuns[] = {
    "tests/data/convergence_cornell_1500.json",  "tests/data/convergence_four_boxes_1000.json",
    "tests/data/convergence_cornell_10000.json", "tests/data/convergence_four_boxes_10000.json",
    "tests/data/convergence_cornell_40000.json", "tests/data/convergence_building_16_20000.json"};

struct Recorded {
  double target = 0;
  std::vector<std::pair<unsigned, double>> passes;  // the last one reaches the target
  double total() const { return passes.back().first; }
};

// Older recordings hold one value per shot (passes of 16), newer ones [shots, convergence] per pass.
Recorded recorded(const std::string& file) {
  const nlohmann::json run = test::readJson(test::sourcePath(file));
  Recorded r{run["target_convergence"], {}};
  const nlohmann::json& h = run["convergence_history"];
  if (h[0].is_array()) {
    for (const auto& p : h)
      if (p[0].get<unsigned>() > 0) r.passes.emplace_back(p[0].get<unsigned>(), p[1].get<double>());
  } else {
    const std::size_t last = h.size() - 1;
    for (std::size_t n = 16; n < last; n += 16) r.passes.emplace_back(unsigned(n), h[n].get<double>());
    r.passes.emplace_back(unsigned(last), h[last].get<double>());
  }
  return r;
}

}  // namespace

TEST_CASE(
    "The first ETA after 10 % of a run is within 25 % of the shots really left, later ones within 2x, on six "
    "recorded runs",
    "[cpu]") {
  for (const char* file : kRuns) {
    INFO(file);
    const Recorded run = recorded(file);
    const double total = run.total();
    EtaModel model;
    double first = NAN, worstHigh = 0, worstLow = 1e9;
    for (const auto& [n, convergence] : run.passes) {
      model.add(n, convergence);
      if (double(n) < 0.1 * total || double(n) >= total) continue;
      const double truth = total - double(n);
      const std::optional<double> left = model.shotsLeft(run.target);
      REQUIRE(left);
      const double ratio = *left / truth;
      if (std::isnan(first)) first = ratio;
      // Near the end a ratio of a few shots means little: there, within 5 % of the run suffices.
      if (std::abs(*left - truth) > 0.05 * total) {
        CHECK(ratio >= 0.5);
        CHECK(ratio <= 2.0);
        worstHigh = std::max(worstHigh, ratio), worstLow = std::min(worstLow, ratio);
      }
    }
    INFO("first estimate / shots left " << first << "; later " << worstLow << " to " << worstHigh);
    CHECK(first >= 0.75);
    CHECK(first <= 1.25);
  }
}

TEST_CASE("The progress bar line never exceeds the terminal width", "[cpu]") {
  StopRule stop;
  stop.targetConvergence = 0.9;
  Progress progress(stop, false);
  SolveStatus s{1234, 0.7712, false};
  const Progress::Estimate e{0.4, 3725.0};
  for (int columns : {10, 30, 50, 80, 200}) {
    const std::string line = progress.barLine(s, e, 12.0, columns);
    INFO(columns << ": '" << line << "'");
    CHECK(int(line.size()) <= columns - 1);
    if (columns >= 80) CHECK(line.find("ETA 1h02m") != std::string::npos);
  }
}

// A recorded run replayed with a 5 s warm-up (shader compiles in the first pass) and 10 ms a shot
// after it: the ETA counts the shots' own rate, not the warm-up spread over them, and the shown
// fraction never falls when the model revises the total up (as its raw share does on four_boxes).
TEST_CASE("The ETA leaves the first pass's warm-up out and the progress fraction never goes backwards", "[cpu]") {
  const char* file = GENERATE(from_range(std::begin(kRuns), std::end(kRuns)));
  INFO(file);
  const Recorded run = recorded(file);
  StopRule stop;
  stop.targetConvergence = run.target;
  Progress progress(stop, false);
  EtaModel raw;  // the model alone, for the raw share
  const double total = run.total(), warmUp = 5.0, perShot = 0.01;
  double shown = 0, rawPrevious = 0, firstRatio = NAN;
  bool rawFell = false;
  for (const auto& [n, convergence] : run.passes) {
    if (double(n) >= total) break;
    const Progress::Estimate e = progress.observe({n, convergence, false}, warmUp + perShot * double(n));
    CHECK(e.fraction >= shown);
    shown = e.fraction;
    raw.add(n, convergence);
    if (auto left = raw.shotsLeft(stop.targetConvergence)) {
      const double share = double(n) / (double(n) + *left);
      rawFell = rawFell || share < rawPrevious;
      rawPrevious = share;
    }
    if (std::isnan(firstRatio) && double(n) >= 0.1 * total && std::isfinite(e.secondsLeft))
      firstRatio = e.secondsLeft / (perShot * (total - double(n)));
  }
  INFO("first ETA after 10 % of the run / the real time left: " << firstRatio << "; the raw share fell: " << rawFell);
  CHECK(firstRatio > 0.75);
  CHECK(firstRatio < 1.25);  // with the warm-up spread over the shots it was 5x
}
