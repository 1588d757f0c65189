// `hairpipe render --light SPEC` (repeatable): a frame lit by a directional, a spot and a point light (the
// last without shadows) renders clean under validation and exports all three in order; bad specs exit 1
// naming the option, the key and the value, writing nothing. `render --environment` renders an environment
// and exports its map. `render --motion-vectors` exports the hair's screen motion.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

TEST(CliRenderLights, RendersThreeLightsAndExportsThemInOrder) {
  const auto png = freshTempPath("hairpipe_cli_render_lights.png");
  const auto dir = freshTempPath("hairpipe_cli_render_lights_export");
  auto r = runCli({"render", "--width", "96", "--height", "72", "--density", "1000", "--frames", "2", "--validation",
                   "--opacity-resolution", "128", "--out", png.string(), "--export-frame", dir.string(),
                   "--light", "directional:dir=0.5,0.8,0.6:color=1,0.9,0.8:intensity=3",
                   "--light", "spot:pos=0.3,0.4,0.6:target=0,-0.08,0:cone=35:range=0.8",
                   "--light", "point:pos=-0.3,0.4,0.5:intensity=2:range=0.5:shadows=off"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(hp::readPngRgba(png).width, 96u);
  const hp::ExportedFrame frame = hp::readFrameExport(dir);
  ASSERT_EQ(frame.lights.size(), 3u);
  EXPECT_EQ(frame.lights[0].type, hp::LightSpec::Type::Directional);
  EXPECT_EQ(frame.lights[0].color, glm::vec3(1.0f, 0.9f, 0.8f));
  EXPECT_EQ(frame.lights[1].type, hp::LightSpec::Type::Spot);
  EXPECT_EQ(frame.lights[1].coneDeg, 35.0f);
  EXPECT_EQ(frame.lights[1].range, 0.8f);
  EXPECT_EQ(frame.lights[2].type, hp::LightSpec::Type::Point);
  EXPECT_EQ(frame.lights[2].position, glm::vec3(-0.3f, 0.4f, 0.5f));
  EXPECT_FALSE(frame.lights[2].shadows);
  EXPECT_TRUE(frame.lights[0].shadows && frame.lights[1].shadows);
  std::filesystem::remove(png);
  std::filesystem::remove_all(dir);
}

// --light-dir still sets the first light, after --light replaced the scene's.
TEST(CliRenderLights, LightDirTurnsTheFirstOfTheGivenLights) {
  const auto png = freshTempPath("hairpipe_cli_render_lights_dir.png");
  const auto dir = freshTempPath("hairpipe_cli_render_lights_dir_export");
  auto r = runCli({"render", "--width", "48", "--height", "36", "--density", "500", "--frames", "1", "--out",
                   png.string(), "--export-frame", dir.string(), "--light", "point:pos=0,0.5,0.5", "--light",
                   "directional:intensity=1", "--light-dir", "0,2,0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const hp::ExportedFrame frame = hp::readFrameExport(dir);
  ASSERT_EQ(frame.lights.size(), 2u);
  EXPECT_EQ(frame.lights[0].type, hp::LightSpec::Type::Directional);
  EXPECT_EQ(frame.lights[0].direction, glm::vec3(0, 1, 0));
  EXPECT_EQ(frame.lights[1].intensity, 1.0f);
  std::filesystem::remove(png);
  std::filesystem::remove_all(dir);
}

TEST(CliRenderLights, BadLightSpecsExitWithAMessageNamingTheKey) {
  const auto png = freshTempPath("hairpipe_cli_render_lights_bad.png");
  std::vector<std::string> nine;
  for (int i = 0; i < 9; ++i) nine.insert(nine.end(), {"--light", "directional"});
  expectRefused({"render", "--frames", "1", "--out", png.string()}, {
      {{"--light", "area:pos=0,1,0"}, "--light 'area:pos=0,1,0': the light type must be directional, spot or point"},
      {{"--light", "point"}, "a point light needs pos=X,Y,Z"},
      {{"--light", "directional:intensity=nan"}, "intensity=nan: must be a finite number"},
      {{"--light", "directional:intensity=-1"}, "intensity=-1: must be >= 0"},
      {{"--light", "spot:pos=0,1,1:cone=95"}, "cone=95: must be in (0, 80] degrees"},
      {{"--light", "point:pos=0,1,x"}, "pos=0,1,x: expected a number"},
      {{"--light", "point:pos=0,1,1:cone=20"}, "'cone' is not a key of a point light"},
      {{"--light", "directional:shadows=maybe"}, "shadows=maybe: expected on or off"},
      {nine, "--light is given 9 times: at most 8 lights"},
  }, png);
}

// --environment studio: the frame renders clean under validation, the export carries the map (its rotation
// and intensity) but not the lights the real-time frame drew for its bright regions; bad environment options
// and files exit 1 naming the option or the file, writing nothing.
TEST(CliRenderEnvironment, RendersTheStudioAndExportsItsMap) {
  const auto png = freshTempPath("hairpipe_cli_render_environment.png");
  const auto dir = freshTempPath("hairpipe_cli_render_environment_export");
  auto r = runCli({"render", "--width", "48", "--height", "36", "--density", "500", "--frames", "1", "--validation",
                   "--opacity-resolution", "64", "--out", png.string(), "--export-frame", dir.string(), "--environment",
                   "studio", "--environment-rotation", "30", "--environment-intensity", "0.5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(hp::readPngRgba(png).width, 48u);
  const hp::ExportedFrame frame = hp::readFrameExport(dir);
  EXPECT_EQ(frame.lights.size(), 1u);  // the sun; the studio's two lights stay out of the export
  EXPECT_EQ(frame.environment, 0.0f);  // the environment is the sky
  ASSERT_TRUE(frame.environmentMap);
  EXPECT_EQ(frame.environmentMap->rotationDeg, 30.0);
  EXPECT_EQ(frame.environmentMap->intensity, 0.5);
  EXPECT_EQ(frame.environmentMap->width, 256u);
  std::filesystem::remove(png);
  std::filesystem::remove_all(dir);
}

TEST(CliRenderEnvironment, BadEnvironmentOptionsExitWithAMessage) {
  const auto png = freshTempPath("hairpipe_cli_render_environment_bad.png");
  const auto text = freshTempPath("hairpipe_cli_environment.hdr");
  { std::ofstream(text) << "no image here\n"; }
  expectRefused({"render", "--frames", "1", "--out", png.string()}, {
      {{"--environment", "/nonexistent/sky.hdr"}, "/nonexistent/sky.hdr"},
      {{"--environment", text.string()}, "not a Radiance .hdr image"},
      {{"--environment", "sky.exr"}, "must be a Radiance .hdr or a .pfm"},
      {{"--environment", "studio", "--environment-intensity", "-1"}, "--environment-intensity must be in [0, 1000]"},
      {{"--environment", "studio", "--environment-rotation", "nan"}, "--environment-rotation must be a finite angle"},
      {{"--environment", "studio", "--environment-lights", "4"}, "--environment-lights must be in [0, 3]"},
  }, png);
  std::filesystem::remove(text);
}

// render --motion-vectors --export-frame: with the head shaking, the exported hair motion (realtime_motion.pfm)
// is pixels where the hair covers the pixel (2.5 px mean at 96x72); with the head still, settling, a tenth
// of that at most. Without
// --export-frame, or with the graphics raster, it is refused.
TEST(CliRenderMotion, ExportsTheHairsMotionOfAShakingHead) {
  const auto png = freshTempPath("hairpipe_cli_render_motion.png");
  const auto meanMotion = [&](const char* animation) {
    const auto dir = freshTempPath(std::string("hairpipe_cli_render_motion_") + animation);
    auto r = runCli({"render", "--width", "96", "--height", "72", "--density", "1500", "--frames", "40",
                     "--animate", animation, "--raster", "compute", "--opacity-resolution", "128", "--out",
                     png.string(), "--export-frame", dir.string(), "--motion-vectors"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const hp::LinearImage motion = hp::readPfm(dir / hp::FrameExportFiles::realtimeMotion);
    const hp::LinearImage alpha = hp::readPfm(dir / hp::FrameExportFiles::realtimeHairAlpha);
    double sum = 0.0;
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < motion.height; ++y)
      for (std::uint32_t x = 0; x < motion.width; ++x)
        if (alpha.at(x, y, 0) > 0.25f) {
          sum += std::hypot(motion.at(x, y, 0), motion.at(x, y, 1));
          ++n;
        }
    std::filesystem::remove_all(dir);
    EXPECT_GT(n, 200u) << animation;
    return n ? sum / double(n) : 0.0;
  };
  const double shaking = meanMotion("shake"), still = meanMotion("none");
  std::cout << "mean hair motion: shaking head " << shaking << " px, still head " << still << " px\n";
  EXPECT_GT(shaking, 1.0);
  EXPECT_LT(still, 0.1 * shaking);
  expectRefused({"render", "--motion-vectors", "--out", png.string()}, {{{}, "give --export-frame DIR"}});
  const auto dir = freshTempPath("hairpipe_cli_render_motion_graphics");
  expectRefused({"render", "--motion-vectors", "--raster", "graphics", "--width", "32", "--height", "24",
                 "--density", "200", "--frames", "1", "--out", png.string(), "--export-frame", dir.string()},
                {{{}, "the graphics raster writes none"}});
  std::filesystem::remove(png);
  std::filesystem::remove_all(dir);
}
