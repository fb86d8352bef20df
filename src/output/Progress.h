// Progress on stderr. On a terminal: a bar redrawn in place with shots, convergence and the ETA,
// sized to the terminal's width (COLUMNS, else the tty's). Otherwise (a log, CI): a plain line
// every few seconds. The ETA models the work left from the convergence curve (src/output/Eta.h)
// rather than extrapolating convergence linearly.
#pragma once
#include <chrono>
#include <cmath>
#include <string>

#include "src/output/Eta.h"
#include "src/solver/Solver.h"

namespace hemirad {

class Progress {
 public:
  Progress(const StopRule& stop, bool enabled);
  void update(const SolveStatus& status);
  void finish();  // ends the bar's line
  double elapsedSeconds() const;

  // The share of the work done and the seconds left (NaN when not yet known), from the stop rule
  // and the model; public for the tests.
  struct Estimate {
    double fraction = 0, secondsLeft = NAN;
  };
  Estimate estimate(const SolveStatus& status, double elapsed) const;
  // The bar line for `columns` terminal columns (never wider).
  std::string barLine(const SolveStatus& status, const Estimate& e, double elapsed, int columns) const;

 private:
  StopRule stop_;
  bool enabled_, tty_;
  EtaModel model_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  bool drawn_ = false;
};

int terminalColumns();  // COLUMNS, else the stderr tty's width, else 80

}  // namespace hemirad
