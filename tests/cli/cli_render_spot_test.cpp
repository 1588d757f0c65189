// `hairpipe render --spot`: a small spot-lit render is clean under validation (and exports), and bad spot options
// exit 1 with a message naming the option, writing nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::freshTempPath;
using hp::test::expectRefused;
using hp::test::runCli;

// With --export-frame: the export carries the spot (for `hairpipe reference`) and the real-time image.
TEST(CliRenderSpot, RendersASpotLitFrameAndExportsIt) {
  const auto png = freshTempPath("hairpipe_cli_render_spot.png");
  const auto dir = freshTempPath("hairpipe_cli_render_spot_export");
  auto r = runCli({"render", "--width", "96", "--height", "72", "--density", "1000", "--frames", "2", "--validation",
                   "--spot", "0.3,0.5,0.8", "--spot-target", "0,-0.05,0", "--spot-angle", "20", "--spot-range", "1",
                   "--opacity-resolution", "128", "--out", png.string(), "--export-frame", dir.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(hp::readPngRgba(png).width, 96u);
  const hp::ExportedFrame frame = hp::readFrameExport(dir);
  ASSERT_EQ(frame.lights.size(), 1u);
  EXPECT_EQ(frame.lights[0].type, hp::LightSpec::Type::Spot);
  EXPECT_EQ(frame.lights[0].position, glm::vec3(0.3f, 0.5f, 0.8f));
  EXPECT_EQ(frame.lights[0].coneDeg, 20.0f);
  EXPECT_EQ(frame.lights[0].range, 1.0f);
  EXPECT_EQ(frame.strands.strandCount, 1000u);
  EXPECT_EQ(hp::readPfm(dir / "realtime.pfm").width, 96u);
  EXPECT_EQ(hp::readPfm(dir / "realtime_hair_alpha.pfm").channels, 1u);
  std::filesystem::remove(png);
  std::filesystem::remove_all(dir);
}

TEST(CliRenderSpot, BadSpotOptionsExitWithAMessageNamingTheOption) {
  const auto png = freshTempPath("hairpipe_cli_render_spot_bad.png");
  expectRefused({"render", "--frames", "1", "--out", png.string()}, {
      {{"--spot", "0,1"}, "--spot"},
      {{"--spot", "0,1,x"}, "--spot"},
      {{"--spot", "0,1,1", "--spot-angle", "0"}, "--spot-angle"},
      {{"--spot", "0,1,1", "--spot-angle", "81"}, "--spot-angle"},
      {{"--spot", "0,1,1", "--spot-range", "-2"}, "--spot-range"},
      {{"--spot", "0,1,1", "--spot-target", "0,1,1"}, "--spot-target"},
      {{"--spot-angle", "20"}, "need --spot"},
      {{"--spot", "0,1,1", "--light-dir", "0,1,0"}, "--light-dir"},
  }, png);
}
