// `hairpipe render --sequence`: every frame a complete PNG, progress on stderr while --json keeps
// stdout JSON, a contact sheet, limits refused up front, and Ctrl-C (SIGINT to the child) stopping
// after the current frame with only complete frame files left and a non-zero exit.
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <regex>
#include <thread>

#include <nlohmann/json.hpp>

#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

namespace {
const std::vector<std::string> kSmall = {"--width", "96", "--height", "72", "--density", "1000",
                                         "--opacity-resolution", "32"};

std::vector<std::string> sequenceArgs(const std::filesystem::path& dir, const std::string& frames) {
  std::vector<std::string> a = {"render", "--sequence", dir.string(), "--frames", frames, "--animate", "shake",
                                "--validation"};
  a.insert(a.end(), kSmall.begin(), kSmall.end());
  return a;
}

// Every entry is frame_NNNN.png and decodes as a whole image of the right size.
std::size_t completeFrames(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(std::regex_match(name, std::regex("frame_[0-9]{4}\\.png"))) << "unexpected file " << name;
    const hp::RgbaImage image = hp::readPngRgba(e.path());
    EXPECT_EQ(image.width, 96u) << name;
    ++n;
  }
  return n;
}
}  // namespace

TEST(CliSequence, WritesEveryFrameWithProgressOnStderrAndJsonOnStdout) {
  const auto dir = freshTempPath("hairpipe_cli_sequence");
  std::filesystem::remove_all(dir);
  const auto sheet = freshTempPath("hairpipe_cli_sequence_sheet.png");
  auto args = sequenceArgs(dir, "2");
  for (const char* a : {"--fps", "30", "--json", "--contact-sheet"}) args.push_back(a);
  args.push_back(sheet.string());
  const auto r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // nothing but JSON on stdout
  EXPECT_EQ(j["frames"], 2);
  EXPECT_EQ(completeFrames(dir), 2u);
  EXPECT_NE(r.err.find("2/2 frames (100%)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("frames/s"), std::string::npos) << r.err;
  const hp::RgbaImage s = hp::readPngRgba(sheet);
  EXPECT_EQ(s.width, 2u * 96u + 2u);  // two tiles in one row, 2-pixel gutters
  EXPECT_EQ(s.height, 72u);
  std::filesystem::remove_all(dir);
  std::filesystem::remove(sheet);
}

// SIGINT and SIGTERM alike: the run stops after the frame being written, exits 1 naming the signal, and
// leaves complete frames only (completeFrames fails on any other file, a temporary one included).
TEST(CliSequence, SigintAndSigtermStopAfterTheCurrentFrameLeavingOnlyCompleteFiles) {
  for (const auto& [sig, name] : {std::pair{SIGINT, "SIGINT"}, std::pair{SIGTERM, "SIGTERM"}}) {
    const auto dir = freshTempPath(std::string("hairpipe_cli_sequence_") + name);
    std::filesystem::remove_all(dir);
    hp::test::CliProcess child(sequenceArgs(dir, "500"));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!std::filesystem::exists(dir / "frame_0001.png") && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    child.signal(sig);
    const auto r = child.wait();
    EXPECT_EQ(r.exitCode, 1) << name;
    EXPECT_NE(r.err.find(std::string("hairpipe: error: interrupted (") + name + ") after frame"), std::string::npos)
        << r.err;
    const std::size_t n = completeFrames(dir);
    EXPECT_GE(n, 1u);
    EXPECT_LT(n, 500u);
    std::filesystem::remove_all(dir);
  }
}

TEST(CliSequence, AbsurdCountsAndConflictingOptionsAreRefusedUpFront) {
  const auto dir = freshTempPath("hairpipe_cli_sequence_bad");
  std::filesystem::remove_all(dir);
  expectRefused({"render", "--width", "32", "--height", "32"}, {
      {{"--sequence", dir.string(), "--frames", "10000"}, "[1, 9999]"},
      {{"--sequence", dir.string(), "--frames", "0"}, "[1, 9999]"},
      {{"--sequence", dir.string(), "--frames", "2", "--fps", "0"}, "--fps"},
      {{"--sequence", dir.string(), "--frames", "2", "--out", "x.png"}, "--out"},
      {{"--contact-sheet", "s.png", "--frames", "1"}, "--contact-sheet needs --sequence"},
  });
  EXPECT_FALSE(std::filesystem::exists(dir));
}
