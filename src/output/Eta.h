// The progress bar's estimate of the work left (src/output/Progress.h). Progressive refinement
// gains most in its first shots (the lights shoot first), so extrapolating convergence linearly
// from the start promises the end far too early (10-20x on the Cornell box at 10 % of the work).
// Instead the unshot share u = 1 - convergence is fitted as a stretched exponential in the shots,
// u = a e^(-k n^0.85), over the shots past the first 30 % (the warm-up, when the lights shoot),
// and solved for the shot count where u reaches 1 - target. A plain exponential (each shot takes
// a fixed share of what is left) promises the end early: the share falls as the bright shooters
// are spent. On six recorded runs (tests/data/: Cornell at 1.5k, 10k, 40k elements, four_boxes at
// 1k and 10k, building_16 at 20k) the first estimate after 10 % of the run is 0.85x-1.19x of the
// shots really left, and later ones 0.81x-1.5x; the exponential was 0.66x-0.99x at 10 %, a power
// law u = a n^-b 2-170x too high.
#pragma once
#include <optional>
#include <utility>
#include <vector>

namespace hemirad {

class EtaModel {
 public:
  // A point of the run: shots done and the convergence after them (NaN: none, e.g. stochastic).
  void add(unsigned shots, double convergence);
  // Shots still to go to reach `targetConvergence` (0 if reached); nothing while the fit has too
  // few points or no downward trend.
  std::optional<double> shotsLeft(double targetConvergence) const;

 private:
  std::vector<std::pair<double, double>> points_;  // (shots, unshot share), shots increasing
};

}  // namespace hemirad
