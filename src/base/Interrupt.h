// SIGINT/SIGTERM during a solve: the handler only records the signal, and the solve loop
// checks it between batches of shots, so the GPU state is whole when it stops (and a final
// checkpoint can be written) instead of the process dying mid-pass.
#pragma once

namespace hemirad {

class InterruptGuard {
 public:
  InterruptGuard();   // installs the handlers
  ~InterruptGuard();  // restores the previous ones
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  // The signal received since construction, or 0.
  static int received();
};

const char* signalName(int signal);

}  // namespace hemirad
