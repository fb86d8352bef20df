// Progress on stderr: a redrawn bar with shots, convergence and ETA when stderr is a
// terminal; nothing while running otherwise (the caller prints one summary line at the end).
#pragma once
#include <chrono>

#include "src/solver/Solver.h"

namespace hemirad {

class Progress {
 public:
  Progress(const StopRule& stop, bool enabled);
  void update(const SolveStatus& status);
  void finish();  // ends the bar's line
  double elapsedSeconds() const;

 private:
  double fraction(const SolveStatus& status) const;
  StopRule stop_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
  bool drawn_ = false;
};

}  // namespace hemirad
