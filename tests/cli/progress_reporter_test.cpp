// The progress reporter (lines off a terminal, a redrawn bar on one, rate-limited, silent for short
// runs) and the contact sheet layout, on the host with an injected clock.
#include <gtest/gtest.h>

#include <sstream>

#include "engine/core/error.h"
#include "samples/tools/contact_sheet.h"
#include "samples/tools/progress_reporter.h"

namespace {
using namespace std::chrono_literals;

struct FakeClock {
  std::chrono::steady_clock::time_point now{};
  hp::ProgressReporter::Clock fn() {
    return [this] { return now; };
  }
};

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}
}  // namespace

TEST(ProgressReporter, PlainLinesAreRateLimitedAndTheLastFrameAlwaysShows) {
  FakeClock clock;
  std::ostringstream out;
  hp::ProgressReporter p(out, "run", 10, {false, 1000ms, 0ms, clock.fn()});
  for (std::uint64_t i = 1; i <= 10; ++i) {
    clock.now += 300ms;  // 3.33 frames/s
    p.update(i);
  }
  p.finish();
  const std::string s = out.str();
  EXPECT_EQ(s.find('\r'), std::string::npos);
  EXPECT_EQ(count(s, "\n"), count(s, "run: "));
  EXPECT_LE(count(s, "run: "), 5u);  // 3 s of run, one line per second at most, plus the last
  EXPECT_NE(s.find("run: 1/10 frames (10%)"), std::string::npos) << s;
  EXPECT_NE(s.find("run: 10/10 frames (100%), 3.33 frames/s, took 3 s"), std::string::npos) << s;
}

TEST(ProgressReporter, ATerminalGetsOneRedrawnBarWithAnEta) {
  FakeClock clock;
  std::ostringstream out;
  hp::ProgressReporter p(out, "run", 4, {true, 0ms, 0ms, clock.fn()});
  clock.now += 2s;
  p.update(1);
  EXPECT_NE(out.str().find("\rrun [#######.....................] 1/4 frames (25%), 0.50 frames/s, ETA 6 s"),
            std::string::npos) << out.str();
  p.update(4);
  p.finish();
  EXPECT_EQ(count(out.str(), "\n"), 1u);  // only the end of the bar's line
}

TEST(ProgressReporter, AShortRunStaysSilent) {
  FakeClock clock;
  std::ostringstream out;
  hp::ProgressReporter p(out, "run", 3, {false, 1000ms, 1000ms, clock.fn()});
  for (std::uint64_t i = 1; i <= 3; ++i) {
    clock.now += 100ms;
    p.update(i);
  }
  p.finish();
  EXPECT_TRUE(out.str().empty()) << out.str();
}

TEST(ContactSheet, TilesFramesInRowsWithGuttersAndPicksEvenlySpreadFrames) {
  std::vector<hp::RgbaImage> frames;
  for (std::uint8_t v : {10, 20, 30}) frames.push_back({2, 1, {v, v, v, 255, v, v, v, 255}});
  const hp::RgbaImage s = hp::contactSheet(frames, 2);
  EXPECT_EQ(s.width, 2u * 2u + 2u);
  EXPECT_EQ(s.height, 2u * 1u + 2u);
  EXPECT_EQ(s.pixels[0], 10);                          // frame 1 top left
  EXPECT_EQ(s.pixels[4 * 4], 20);                      // frame 2 after the gutter
  EXPECT_EQ(s.pixels[(3 * s.width) * 4], 30);          // frame 3 on the second row
  EXPECT_EQ(hp::sheetFrames(100, 4), (std::vector<std::uint32_t>{1, 34, 67, 100}));
  EXPECT_EQ(hp::sheetFrames(3, 12), (std::vector<std::uint32_t>{1, 2, 3}));
  frames[1].width = 1;
  EXPECT_THROW(hp::contactSheet(frames, 2), hp::Error);
}
