#include "samples/tools/interrupt_flag.h"

#include "engine/core/error.h"

namespace hp {
namespace {
volatile std::sig_atomic_t gRequested = 0;
bool gInstalled = false;
extern "C" void onInterrupt(int) { gRequested = 1; }
}  // namespace

InterruptFlag::InterruptFlag() {
  if (gInstalled) throw Error("InterruptFlag: only one may be installed at a time");
  gRequested = 0;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigemptyset(&action.sa_mask);
  if (sigaction(SIGINT, &action, &previous_) != 0) throw Error("InterruptFlag: sigaction(SIGINT) failed");
  gInstalled = true;
}

InterruptFlag::~InterruptFlag() {
  sigaction(SIGINT, &previous_, nullptr);
  gInstalled = false;
}

bool InterruptFlag::requested() const { return gRequested != 0; }
}  // namespace hp
