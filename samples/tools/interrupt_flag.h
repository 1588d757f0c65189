#pragma once
// Contract: Ctrl-C (SIGINT) as a request to stop, for long runs that must end between two frames so
// every file they wrote is complete. While an InterruptFlag lives, SIGINT only sets the flag (the
// run polls requested() after each frame); its destructor restores the previous handler. One at a time.
#include <csignal>

namespace hp {
class InterruptFlag {
 public:
  InterruptFlag();
  ~InterruptFlag();
  InterruptFlag(const InterruptFlag&) = delete;
  InterruptFlag& operator=(const InterruptFlag&) = delete;
  bool requested() const;

 private:
  struct sigaction previous_ {};
};
}  // namespace hp
