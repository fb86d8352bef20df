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
  // Seconds a shot takes are measured from the first status on: the first pass carries shader
  // compiles and uploads (warm-up), which extrapolated over the run promised hours for minutes.
  // The fraction never goes backwards: a model revising its total down shows no progress lost.
  Estimate estimate(const SolveStatus& status, double elapsed) const;
  // Takes a status `elapsed` seconds into the run into the model; the estimate to show (update's
  // first step, public for the tests).
  Estimate observe(const SolveStatus& status, double elapsed);
  // The bar line for `columns` terminal columns (never wider).
  std::string barLine(const SolveStatus& status, const Estimate& e, double elapsed, int columns) const;

 private:
  StopRule stop_;
  bool enabled_, tty_;
  EtaModel model_;
  unsigned firstShots_ = 0;  // the first status seen: shots and seconds, where the rate starts
  double firstSeconds_ = 0, shownFraction_ = 0;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  bool drawn_ = false;
};

int terminalColumns();  // COLUMNS, else the stderr tty's width, else 80

}  // namespace hemirad
