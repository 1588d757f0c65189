// `hairpipe view` under a private Xvfb on lavapipe, with validation (sync on; any message fails the
// run): the window shows hair (green hair, so its pixels cannot be mistaken for skin or background),
// and a resize in the middle of the run recreates the swapchain and keeps drawing at the new size.
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
}  // namespace

TEST(CliView, ShowsHairUnderXvfbAndKeepsWorkingAcrossAResize) {
  hp::test::Xvfb x;
  const auto png = freshTempPath("hairpipe_cli_view.png");
  auto r = runCli({"view", "--frames", "6", "--resize-at", "3:160x120", "--width", "128", "--height", "96",
                   "--density", "2000", "--opacity-resolution", "32", "--color", "0.2,0.75,0.25", "--exposure", "4", "--validation",
                   "--json", "--screenshot", png.string()},
                  {x.displayEnv()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 6);
  EXPECT_EQ(j["raster"], "compute");  // what `render` uses on lavapipe
  EXPECT_GE(j["swapchain_recreations"].get<int>(), 1);
  const hp::RgbaImage image = hp::readPngRgba(png);
  EXPECT_EQ(image.width, 160u);  // the screenshot is the resized window's last frame
  EXPECT_EQ(image.height, 120u);
  // --exposure 4: the hair away from the light shows through its ambient, sky albedo x 0.15 of the sky.
  const double hair = greenFraction(image);
  EXPECT_GT(hair, 0.05) << "hair fraction of the window";
  EXPECT_LT(hair, 0.7) << "hair fraction of the window";
  std::filesystem::remove(png);
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
  }, png);
}
