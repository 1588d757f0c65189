// `hairpipe view` under a private Xvfb on lavapipe, with validation (sync on; any message fails the
// run): the window shows hair (green hair, so its pixels cannot be mistaken for skin or background)
// after 30 frames with a resize, a minimise and an out-of-date swapchain on the way; a lost device is
// replaced and the run goes on; a device lost over and over ends the run with a message and no image.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

namespace {
// Green hair: green clearly above red and blue.
double greenFraction(const hp::RgbaImage& image) {
  std::size_t green = 0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 4) {
    const int r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
    if (g > r + 12 && g > b + 12) ++green;
  }
  return double(green) / double(image.width * image.height);
}

// What every run here views: the scalp cap (49 guides grown on it, a sphere for a head) with 2000 green
// render strands in a small window. The default head costs 3 s more CPU to build (its distance field and
// mesh) and 40 % more per frame (its 2130 guides and head mesh): the viewer is the same. --exposure 4: hair
// away from the light shows through its ambient alone (sky albedo x 0.15 of the sky).
std::vector<std::string> viewArgs(const std::string& frames, const std::filesystem::path& png,
                                  const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"view", "--model", std::string(HAIRPIPE_TEST_DATA_DIR) + "/scalp_cap.obj",
                                   "--frames", frames, "--width", "128", "--height", "96", "--density", "2000",
                                   "--opacity-resolution", "32", "--color", "0.2,0.75,0.25", "--exposure", "4",
                                   "--validation", "--json",
                                   "--screenshot", png.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

void expectHair(const std::filesystem::path& png, std::uint32_t width, std::uint32_t height) {
  const hp::RgbaImage image = hp::readPngRgba(png);
  EXPECT_EQ(image.width, width);
  EXPECT_EQ(image.height, height);
  const double hair = greenFraction(image);
  EXPECT_GT(hair, 0.05) << "hair fraction of the window";
  EXPECT_LT(hair, 0.7) << "hair fraction of the window";
}

bool saysValidation(const std::string& err) { return err.find("vulkan validation") != std::string::npos; }
}  // namespace

// The viewer's acceptance run: 30 frames and a screenshot. On the way the window is resized (frame 5), minimised for
// 0.3 s (frame 12: nothing is drawn meanwhile, the frames still all come) and a present reports the
// swapchain out of date (frame 20: recreated, the run goes on).
TEST(CliView, ThirtyFramesShowHairAcrossAResizeAMinimiseAndAnOutOfDateSwapchain) {
  hp::test::Xvfb x;
  const auto png = freshTempPath("hairpipe_cli_view.png");
  auto r = runCli(viewArgs("30", png, {"--resize-at", "5:160x120", "--minimise-at", "12:0.3", "--fault-at",
                                       "20:vkQueuePresentKHR:VK_ERROR_OUT_OF_DATE_KHR"}),
                  {x.displayEnv()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(saysValidation(r.err)) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 30);
  EXPECT_EQ(j["raster"], "compute");  // what `render` uses on lavapipe
  EXPECT_EQ(j["swapchain_recreations"], 2) << "one for the resize, one for the out-of-date present";
  EXPECT_EQ(j["minimised_waits"], 1);
  EXPECT_EQ(j["device_losses"], 0);
  expectHair(png, 160, 120);  // the screenshot is the resized window's last frame
  std::filesystem::remove(png);
}

// A device lost in the middle of the run (the frame fence's wait, frame 4) is destroyed with everything on
// it; the viewer says so and goes on with a new device to the last frame, which shows hair.
TEST(CliView, ALostDeviceIsReplacedAndTheRunGoesOn) {
  hp::test::Xvfb x;
  const auto png = freshTempPath("hairpipe_cli_view_lost.png");
  auto r = runCli(viewArgs("8", png, {"--fault-at", "4:vkWaitForFences:VK_ERROR_DEVICE_LOST"}), {x.displayEnv()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(saysValidation(r.err)) << r.err;
  EXPECT_NE(r.err.find("hairpipe: vkWaitForFences("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("failed: VK_ERROR_DEVICE_LOST (-4); starting again on a new device"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 8);
  EXPECT_EQ(j["device_losses"], 1);
  expectHair(png, 128, 96);
  std::filesystem::remove(png);
}

// A device that is lost again and again before a frame is drawn (the submit of frame 2, three times) ends
// the run: exit 1, a message naming the failure and the count, no screenshot, no validation message.
TEST(CliView, ADeviceLostOverAndOverEndsTheRunWithAMessage) {
  hp::test::Xvfb x;
  const auto png = freshTempPath("hairpipe_cli_view_gone.png");
  const std::string lost = "2:vkQueueSubmit2:VK_ERROR_DEVICE_LOST";
  auto r = runCli(viewArgs("4", png, {"--fault-at", lost, "--fault-at", lost, "--fault-at", lost}), {x.displayEnv()});
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_FALSE(saysValidation(r.err)) << r.err;
  EXPECT_NE(r.err.find("hairpipe: error: vkQueueSubmit2("), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("failed: VK_ERROR_DEVICE_LOST (-4): the device was lost 3 times"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lost 3 times in a row without a frame drawn"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(CliView, BadOptionsAreRefusedBeforeAWindowOpens) {
  const auto png = freshTempPath("hairpipe_cli_view_bad.png");
  expectRefused({"view", "--screenshot", png.string()}, {
      {{}, "--screenshot needs --frames"},
      {{"--frames", "2", "--resize-at", "2:0x10"}, "--resize-at"},
      {{"--frames", "2", "--resize-at", "bogus"}, "--resize-at"},
      {{"--frames", "2", "--width", "0"}, "width"},
      {{"--frames", "2000000"}, "at most 1000000"},
      {{"--frames", "2", "--opacity-resolution", "8"}, "resolution"},
      {{"--frames", "2", "--exposure", "3e38"}, "--exposure must be in (0, 1e6], got 3e+38"},
      {{"--frames", "2", "--minimise-at", "1:0"}, "--minimise-at"},
      {{"--frames", "2", "--fault-at", "1:vkAcquireNextImageKHR:VK_ERROR_OUT_OF_DATE_KHR"}, "--fault-at"},
      {{"--frames", "2", "--fault-at", "1:vkWaitForFences:VK_ERROR_OUT_OF_DATE_KHR"}, "--fault-at"},
      {{"--frames", "2", "--fault-at", "x:vkQueuePresentKHR:VK_SUBOPTIMAL_KHR"}, "--fault-at"},
  }, png);
}
