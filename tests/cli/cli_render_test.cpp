#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::freshTempPath;
using hp::test::expectRefused;
using hp::test::runCli;

TEST(CliRender, WritesThePngReportsEveryPassAndDumpsTheStrands) {
  const auto png = freshTempPath("hairpipe_cli_render.png");
  const auto strands = freshTempPath("hairpipe_cli_render.hair");
  auto r = runCli({"render", "--width", "128", "--height", "96", "--density", "2000", "--frames", "5", "--validation",
                   "--json", "--out", png.string(), "--dump-strands", strands.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["raster"], "compute");  // auto on lavapipe
  for (const char* pass : {"simulate", "tessellate", "interpolate", "bounds", "opacity", "head", "raster project", "raster shade",
                           "raster bin", "raster fine", "composite", "composite pass", "tonemap"})
    EXPECT_GT(j["gpu_ms"][pass].get<double>(), 0.0) << pass;
  EXPECT_GT(j["raster_lists"]["kept"].get<double>(), 0.0);
  EXPECT_EQ(j["raster_lists"]["overflow"], 0);
  EXPECT_EQ(j["strands"], 2000);
  // At 128x96 every pair of segments is within the default shading spacing: at most 19 of 36 per strand.
  EXPECT_GT(j["raster_lists"]["shaded_vertices"].get<double>(), 0.0);
  EXPECT_LE(j["raster_lists"]["shaded_vertices"].get<double>(), 2000.0 * 19.0);
  hp::RgbaImage image = hp::readPngRgba(png);
  EXPECT_EQ(image.width, 128u);
  EXPECT_EQ(image.height, 96u);
  hp::HairFileData dump = hp::readHairFile(strands);
  EXPECT_EQ(dump.pointCount(), 2000u * j["vertices_per_strand"].get<std::uint32_t>());
  std::filesystem::remove(png);
  std::filesystem::remove(strands);
}

// The hair grid in the renderer's frame (its own passes before the simulation), under validation.
TEST(CliRender, TheHairGridRunsInTheFrame) {
  const auto png = freshTempPath("hairpipe_cli_render_grid.png");
  auto r = runCli({"render", "--width", "96", "--height", "64", "--density", "1000", "--frames", "3", "--validation",
                   "--volume", "0.6", "--friction", "0.1", "--json", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["gpu_ms"]["simulate grid"].get<double>(), 0.0) << r.out;
  EXPECT_GT(j["gpu_ms"]["simulate"].get<double>(), 0.0);
  std::filesystem::remove(png);
}

TEST(CliRender, TheGraphicsRasterStaysSelectable) {
  const auto png = freshTempPath("hairpipe_cli_render_graphics.png");
  auto r = runCli({"render", "--width", "96", "--height", "64", "--density", "1000", "--frames", "2", "--validation",
                   "--json", "--raster", "graphics", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["raster"], "graphics");
  EXPECT_GT(j["gpu_ms"]["shade"].get<double>(), 0.0);
  EXPECT_FALSE(j.contains("raster_lists"));
  std::filesystem::remove(png);
}

// The largest device-local heap of the device the tool selects, from `hairpipe info --json`.
double selectedDeviceLocalHeapMiB() {
  auto r = runCli({"info", "--json"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  double largest = 0;
  for (const auto& d : j["devices"])
    if (d["index"] == j["selected"])
      for (const auto& h : d["heaps"])
        if (h["device_local"].get<bool>()) largest = std::max(largest, h["size_mib"].get<double>());
  return largest;
}

TEST(CliRender, BadOptionsExitWithAMessageAndWriteNothing) {
  const auto png = freshTempPath("hairpipe_cli_render_bad.png");
  std::vector<hp::test::RefusedCase> cases = {
      {{"--width", "0"}, "width"},          {{"--msaa", "3"}, "msaa"},
      {{"--raster", "bogus"}, "bogus"},     {{"--tile-budget", "0"}, "tileBudget"},
      {{"--lines", "--raster", "compute"}, "--lines"},
      {{"--lut-mode", "bogus"}, "bogus"},   {{"--light-dir", "0,0,0"}, "light-dir"},
      {{"--exposure", "-1"}, "exposure"},   {{"--eta", "0.5"}, "eta"},
      {{"--exposure", "3e38"}, "exposure must be in (0, 1e6], got 3e+38"},
      {{"--animate", "spin"}, "spin"},      {{"--density", "0"}, "total"},
      {{"--width", "16385"}, "--width/--height must be in [1, 16384]"},
      {{"--camera-orbit", "inf"}, "--camera-orbit must be a finite angle"},
      {{"--clump", "2.5,0.5"}, "--clump: COUNT must be a whole number in [0, 64]"},
      {{"--curl", "0.01,nan"}, "GroomSettings.curlTurns"},
      {{"--frizz", "-1"}, "GroomSettings.frizzAmplitude"},
      {{"--frizz", "0.002,40,3,0"}, "GroomSettings.frizzHairlineWidth"},
      {{"--bounce-samples", "1"}, "--bounce-samples must be in [2, 256]"},
      {{"--volume", "11"}, "simulation parameter volume must be in [0, 10], got 11"},
      {{"--grid-resolution", "3"}, "gridResolution must be in [4, 128], got 3"},
      {{"--shading-spacing", "-1"}, "shadingSpacing must be in [0, 4096] pixels, got -1"},
  };
  // Render targets past half the device-local heap are refused before anything is allocated. The largest
  // frame the options allow (16384^2 at msaa 8: 108 bytes a pixel, 27.6 GiB) exceeds that on lavapipe
  // (2 GiB heap) but not on a GPU with 80 GB, where the case cannot be built and is left out.
  const double largestFrameMiB = 16384.0 * 16384.0 * 108.0 / (1 << 20);
  if (largestFrameMiB > 0.5 * selectedDeviceLocalHeapMiB())
    cases.push_back({{"--width", "16384", "--height", "16384", "--msaa", "8"}, "device-local heap"});
  expectRefused({"render", "--frames", "1", "--out", png.string()}, cases, png);
}
