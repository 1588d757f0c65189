#include "samples/tools/progress_reporter.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace hp {
namespace {
constexpr int kBarWidth = 28;

std::string bar(std::uint64_t done, std::uint64_t total) {
  const int filled = total ? int(double(done) / double(total) * kBarWidth) : kBarWidth;
  return "[" + std::string(std::size_t(filled), '#') + std::string(std::size_t(kBarWidth - filled), '.') + "]";
}

std::string duration(double seconds) {
  char text[32];
  const long s = long(std::lround(seconds));
  if (s >= 3600) std::snprintf(text, sizeof(text), "%ldh%02ldm", s / 3600, (s / 60) % 60);
  else if (s >= 60) std::snprintf(text, sizeof(text), "%ldm%02lds", s / 60, s % 60);
  else std::snprintf(text, sizeof(text), "%ld s", s);
  return text;
}
}  // namespace

ProgressReporter::ProgressReporter(std::ostream& out, std::string label, std::uint64_t total, Options options)
    : out_(out), label_(std::move(label)), total_(total), options_(std::move(options)) {
  start_ = lastShown_ = options_.clock();
}

namespace {
ProgressReporter::Options stderrOptions(std::chrono::milliseconds delay) {
  ProgressReporter::Options o;
  o.terminal = isatty(STDERR_FILENO) == 1;
  o.delay = delay;
  return o;
}
}  // namespace

ProgressReporter::ProgressReporter(std::string label, std::uint64_t total, std::chrono::milliseconds delay)
    : ProgressReporter(std::cerr, std::move(label), total, stderrOptions(delay)) {}

ProgressReporter::~ProgressReporter() {
  // A run that stopped early (error, Ctrl-C) still ends the terminal's bar line.
  if (options_.terminal && shownAny_ && !finished_) out_ << "\n" << std::flush;
}

std::string ProgressReporter::summary(std::uint64_t done, std::uint64_t total, double seconds) {
  char text[160];
  const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
  const int percent = total ? int(100.0 * double(done) / double(total)) : 100;
  std::string eta = "ETA --";
  if (done >= total) eta = "took " + duration(seconds);
  else if (rate > 0.0) eta = "ETA " + duration(double(total - done) / rate);
  std::snprintf(text, sizeof(text), "%llu/%llu frames (%d%%), %.2f frames/s, ", (unsigned long long)done,
                (unsigned long long)total, percent, rate);
  return text + eta;
}

void ProgressReporter::update(std::uint64_t done) {
  done_ = done;
  const auto now = options_.clock();
  if (!shownAny_ && now - start_ < options_.delay) return;
  if (shownAny_ && done < total_ && now - lastShown_ < options_.interval) return;
  lastShown_ = now;
  show(done);
}

void ProgressReporter::finish() {
  if (finished_) return;
  finished_ = true;
  if (!shownAny_) return;  // a short run stays silent
  if (shownDone_ != done_) show(done_);
  if (options_.terminal) out_ << "\n" << std::flush;
}

void ProgressReporter::show(std::uint64_t done) {
  const double seconds = std::chrono::duration<double>(options_.clock() - start_).count();
  if (options_.terminal)
    out_ << "\r" << label_ << " " << bar(done, total_) << " " << summary(done, total_, seconds) << "\x1b[K" << std::flush;
  else
    out_ << label_ << ": " << summary(done, total_, seconds) << "\n" << std::flush;
  shownAny_ = true;
  shownDone_ = done;
}
}  // namespace hp
