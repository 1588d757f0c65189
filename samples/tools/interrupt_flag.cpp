#include "samples/tools/interrupt_flag.h"

#include "engine/core/error.h"

namespace hp {
namespace {
volatile std::sig_atomic_t gSignal = 0;  // the signal that asked to stop, 0 for none
bool gInstalled = false;
extern "C" void onInterrupt(int signal) { gSignal = signal; }
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
}

bool InterruptFlag::requested() const { return gSignal != 0; }

bool interruptRequested() { return gSignal != 0; }

void throwIfInterrupted(const std::string& where) {
  const int signal = gSignal;
  if (signal == 0) return;
  throw Error(std::string("interrupted (") + (signal == SIGTERM ? "SIGTERM" : "SIGINT") + ") " + where);
}
}  // namespace hp
