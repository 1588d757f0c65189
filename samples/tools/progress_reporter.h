#pragma once
// Contract: progress of a long run of frames on stderr (never stdout, which `--json` keeps for JSON):
// frames done of the total, frames per second and the time left. On a terminal one bar is redrawn in
// place; otherwise (a pipe, a log file) plain lines are written. Either way at most one update per
// `interval` (the last frame always shows once anything has), so a fast run does not flood the log,
// and nothing before `delay`: a run shorter than that stays silent.
// The clock is injectable so tests can drive it; update() and finish() never throw.
#include <chrono>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

namespace hp {
class ProgressReporter {
 public:
  using Clock = std::function<std::chrono::steady_clock::time_point()>;
  struct Options {
    bool terminal = false;                                   // redraw a bar instead of writing lines
    std::chrono::milliseconds interval{1000};                // least time between two updates
    std::chrono::milliseconds delay{1000};                   // silence at the start
    Clock clock = [] { return std::chrono::steady_clock::now(); };
  };

  ProgressReporter(std::ostream& out, std::string label, std::uint64_t total, Options options);
  // stderr, redrawn when stderr is a terminal.
  ProgressReporter(std::string label, std::uint64_t total, std::chrono::milliseconds delay = std::chrono::milliseconds(1000));
  ~ProgressReporter();

  void update(std::uint64_t done);
  // The final state (once): the last line, and the terminal's bar ended by a newline.
  void finish();

  // "12/60 frames (20%), 3.4 frames/s, ETA 14 s" — what each update shows after the bar or label.
  static std::string summary(std::uint64_t done, std::uint64_t total, double seconds);

 private:
  void show(std::uint64_t done);

  std::ostream& out_;
  std::string label_;
  std::uint64_t total_;
  Options options_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point lastShown_;
  std::uint64_t done_ = 0;
  std::uint64_t shownDone_ = 0;
  bool shownAny_ = false;
  bool finished_ = false;
};
}  // namespace hp
