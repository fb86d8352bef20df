#include "src/base/Interrupt.h"

#include <csignal>

namespace hemirad {

namespace {
volatile std::sig_atomic_t gReceived = 0;
struct sigaction gPrevious[2];
constexpr int kSignals[2] = {SIGINT, SIGTERM};

extern "C" void record(int signal) { gReceived = signal; }
}  // namespace

InterruptGuard::InterruptGuard() {
  gReceived = 0;
  struct sigaction action {};
  action.sa_handler = record;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &action, &gPrevious[i]);
}

InterruptGuard::~InterruptGuard() {
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &gPrevious[i], nullptr);
}

int InterruptGuard::received() { return gReceived; }

const char* signalName(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

}  // namespace hemirad
