#include "samples/tools/interrupt_flag.h"

#include <atomic>

#include "engine/core/error.h"

namespace hp {
namespace {
// The signal that asked to stop, 0 for none; lock-free, so the handler may write it and worker threads
// (the path tracer's) read it.
std::atomic<int> gSignal{0};
static_assert(std::atomic<int>::is_always_lock_free);
bool gInstalled = false;
// A second signal while the first waits for a safe point stops the process the default way (a command
// that never reaches one can still be ended).
extern "C" void onInterrupt(int signal) {
  if (gSignal.exchange(signal) != 0) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}
}  // namespace

InterruptFlag::InterruptFlag() {
  if (gInstalled) throw Error("InterruptFlag: only one may be installed at a time");
  gSignal = 0;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  if (sigaction(SIGINT, &action, &previousInt_) != 0) throw Error("InterruptFlag: sigaction(SIGINT) failed");
  if (sigaction(SIGTERM, &action, &previousTerm_) != 0) {
    sigaction(SIGINT, &previousInt_, nullptr);
    throw Error("InterruptFlag: sigaction(SIGTERM) failed");
  }
  gInstalled = true;
}

InterruptFlag::~InterruptFlag() {
  sigaction(SIGINT, &previousInt_, nullptr);
  sigaction(SIGTERM, &previousTerm_, nullptr);
  gInstalled = false;
  gSignal = 0;
}

bool InterruptFlag::requested() const { return gSignal != 0; }

bool interruptRequested() { return gSignal != 0; }

void throwIfInterrupted(const std::string& where) {
  const int signal = gSignal.load();
  if (signal == 0) return;
  throw Error(std::string("interrupted (") + (signal == SIGTERM ? "SIGTERM" : "SIGINT") + ") " + where);
}
}  // namespace hp
