// The progress bar's estimate of the work left (src/output/Progress.h). Progressive refinement
// gains most in its first shots (the lights shoot first), so extrapolating convergence linearly
// from the start promises the end far too early (10-20x on the Cornell box at 10 % of the work).
// Instead the unshot share u = 1 - convergence is fitted as an exponential in the shots over the
// recent half of the run, u = a e^(-k n) (ln u a line in n: each shot takes a share of what is
// left), and solved for the shot count where u reaches 1 - target. On recorded histories
// (tests/data/) it is within 0.66x-1.66x of the shots really left from 10 % of the run on; a power
// law u = a n^-b fitted the same way was 2-170x too high.
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
