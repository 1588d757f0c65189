#pragma once
// Contract: SIGINT (Ctrl-C) and SIGTERM as a request to stop, for long runs that must end at a safe point
// so every file they wrote is complete and no temporary file is left. While an InterruptFlag lives, the
// two signals only set the flag; the run polls interruptRequested() at its safe points (between frames,
// tiles, cases) and stops with throwIfInterrupted(), whose hp::Error names the signal. The destructor
// restores the previous handlers. A second signal before the run reached a safe point ends the process the
// default way. One at a time (the CLI installs one around every command, and fails a command that finished
// after a signal, saying so).
#include <csignal>
#include <string>

namespace hp {
class InterruptFlag {
 public:
  InterruptFlag();
  ~InterruptFlag();
  InterruptFlag(const InterruptFlag&) = delete;
  InterruptFlag& operator=(const InterruptFlag&) = delete;
  bool requested() const;

 private:
  struct sigaction previousInt_ {};
  struct sigaction previousTerm_ {};
};

// Whether SIGINT or SIGTERM arrived while an InterruptFlag was installed (false without one).
bool interruptRequested();
// Throws hp::Error "interrupted (SIGINT|SIGTERM) <where>" when one did; nothing otherwise.
void throwIfInterrupted(const std::string& where);
}  // namespace hp
