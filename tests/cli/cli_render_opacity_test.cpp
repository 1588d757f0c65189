// `hairpipe render --dump-opacity DIR`: the 16 slices as PFM (size, finite, non-decreasing in i), the
// contact sheet PNG and the slice depths JSON (z_i = z_near + i d_z), the bounds and opacity passes
// in the reported GPU times; refused shadow options exit 1 naming the option or field.
// --skin-color reaches the exported frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;
namespace fs = std::filesystem;

namespace {
fs::path tempDir(const std::string& name) {
  fs::path dir = fs::path(::testing::TempDir()) / "hairpipe_cli_render_opacity" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// A 1-channel little-endian PFM: width, height, values.
std::vector<float> readPfm(const fs::path& path, std::uint32_t& width, std::uint32_t& height) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  float scale = 0;
  in >> magic >> width >> height >> scale;
  in.get();
  EXPECT_EQ(magic, "Pf");
  EXPECT_LT(scale, 0.0f) << "little-endian";
  std::vector<float> v(std::size_t(width) * height);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(v.size() * 4));
  EXPECT_TRUE(bool(in)) << path;
  return v;
}

std::vector<std::string> baseArgs(const fs::path& dir) {
  return {"render", "--width", "64", "--height", "48", "--msaa", "1", "--density", "800", "--frames", "2",
          "--opacity-resolution", "64", "--out", (dir / "img.png").string()};
}
}  // namespace

TEST(CliRenderOpacity, DumpsSlicesContactSheetAndDepths) {
  const fs::path dir = tempDir("dump");
  auto args = baseArgs(dir);
  for (const char* a : {"--dump-opacity", "", "--json", "--validation"}) args.push_back(a);
  args[args.size() - 3] = (dir / "maps").string();
  auto r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto report = nlohmann::json::parse(r.out);
  EXPECT_TRUE(report["gpu_ms"].contains("bounds"));
  EXPECT_TRUE(report["gpu_ms"].contains("opacity"));

  auto depths = nlohmann::json::parse(std::ifstream(dir / "maps" / "opacity_slices.json"));
  EXPECT_EQ(depths["resolution"].get<int>(), 64);
  const double zNear = depths["z_near"], zFar = depths["z_far"], dz = depths["d_z"];
  EXPECT_LT(zNear, zFar);
  EXPECT_NEAR(dz, (zFar - zNear) / 16.0, 1e-6);
  ASSERT_EQ(depths["slice_depths"].size(), 16u);
  for (int i = 1; i <= 16; ++i) EXPECT_NEAR(depths["slice_depths"][i - 1].get<double>(), zNear + i * dz, 1e-5);

  std::vector<float> previous;
  for (int i = 1; i <= 16; ++i) {
    std::ostringstream name;
    name << "opacity_slice_" << (i < 10 ? "0" : "") << i << ".pfm";
    std::uint32_t w = 0, h = 0;
    std::vector<float> slice = readPfm(dir / "maps" / name.str(), w, h);
    ASSERT_EQ(w, 64u);
    ASSERT_EQ(h, 64u);
    std::size_t decreasing = 0;
    for (std::size_t t = 0; t < slice.size(); ++t) {
      ASSERT_TRUE(std::isfinite(slice[t]));
      if (!previous.empty()) decreasing += slice[t] < previous[t];
    }
    EXPECT_EQ(decreasing, 0u) << "slice " << i;
    previous = slice;
  }
  float last = 0;
  for (float v : previous) last = std::max(last, v);
  EXPECT_GT(last, 0.0f) << "slice 16 holds hair";
  const hp::RgbaImage sheet = hp::readPngRgba(dir / "maps" / "opacity_contact_sheet.png");
  EXPECT_EQ(sheet.width, 4u * 64u);
  EXPECT_EQ(sheet.height, 4u * 64u);
  for (const auto& entry : fs::directory_iterator(dir / "maps"))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << "left a temporary file";
}

TEST(CliRenderOpacity, RefusesBadShadowOptions) {
  const fs::path dir = tempDir("bad");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--opacity-resolution", "0"}, "resolution"},
      {{"--opacity-resolution", "100000"}, "resolution"},
      {{"--strand-opacity", "-1"}, "strandOpacity"},
      {{"--strand-opacity", "nan"}, "strandOpacity"},
      {{"--shadow-k", "-2"}, "k must be"},
      {{"--shadow-bias", "40"}, "biasSlices"},
      {{"--opacity-raster", "splat"}, "opacity raster must be auto, compute or graphics"},
      {{"--scattering", "triple"}, "scattering must be single or dual"},
      {{"--skin-bounce", "maybe"}, "--skin-bounce must be on or off, got 'maybe'"},
      {{"--skin-indirect", "yes"}, "--skin-indirect must be on or off, got 'yes'"},
      {{"--far-side", "closed"}, "--far-side must be depth or open, got 'closed'"},
      {{"--skin-color", "2,0,0"}, "--skin-color components must be in [0, 1]"},
      {{"--skin-color", "0.5,nan,0.5"}, "--skin-color must be finite"},
      {{"--scattering", "dual", "--lut-mode", "float"}, "--scattering dual needs the physical fibre model"},
      {{"--no-shadows", "--dump-opacity", (dir / "x").string()}, "--dump-opacity"},
  };
  for (const auto& [extra, needle] : cases) {
    auto args = baseArgs(dir);
    args.insert(args.end(), extra.begin(), extra.end());
    auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 1) << extra.front();
    EXPECT_NE(r.err.find(needle), std::string::npos) << extra.front() << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir / "img.png")) << "no output after a refused option";
}

// Deep opacity maps are the default (with their own bias, 0.25 deep slices); --global-opacity turns them off
// and --shadow-bias sets the bias of the slices in effect. The dump records what the frame used.
TEST(CliRenderOpacity, DeepMapsByDefaultGlobalOnRequest) {
  const fs::path dir = tempDir("deep");
  auto dumped = [&](std::vector<std::string> extra) {
    auto args = baseArgs(dir);
    args.insert(args.end(), {"--opacity-raster", "compute", "--dump-opacity", (dir / "maps").string()});
    args.insert(args.end(), extra.begin(), extra.end());
    auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return nlohmann::json::parse(std::ifstream(dir / "maps" / "opacity_slices.json"));
  };
  const auto byDefault = dumped({});
  EXPECT_TRUE(byDefault["deep"].get<bool>());
  EXPECT_FLOAT_EQ(byDefault["deep_bias_slices"].get<float>(), 0.25f);
  EXPECT_FLOAT_EQ(byDefault["bias_slices"].get<float>(), 1.0f);
  const auto global = dumped({"--global-opacity", "--shadow-bias", "0.75"});
  EXPECT_FALSE(global["deep"].get<bool>());
  EXPECT_FLOAT_EQ(global["bias_slices"].get<float>(), 0.75f);
}

// --skin-color reaches the frame: the export's skin colour and head albedo (away from the scalp) are the
// given colour (the refusals are in the list above), and so do the pixels. Two frames from the front
// (face, neck and shoulders in view) differ only in the skin's red, 0.2 -> 0.8. Without the skin's indirect
// light (whose bounces between parts of the skin grow faster than the albedo: albedo / (1 - albedo x blocked))
// the head's radiance is albedo x light per channel (shaders/head.frag), so in the exported linear image
// (realtime.pfm, before exposure) a pixel that sees only skin has 4x the red and the same green and blue;
// pixels where hair or background cover part of the skin change less. Skin pixels = red at least doubled.
TEST(CliRenderOpacity, SkinColorReachesTheExportedFrame) {
  auto render = [](const std::string& name, const std::string& color) {
    const fs::path dir = tempDir(name);
    auto args = baseArgs(dir);
    args.insert(args.end(), {"--camera-orbit", "0", "--skin-color", color, "--skin-indirect", "off", "--export-frame",
                             (dir / "frame").string()});
    auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return dir / "frame";
  };
  const fs::path dimDir = render("skin", "0.2,0.3,0.4");
  const fs::path redDir = render("skin_red", "0.8,0.3,0.4");
  const hp::ExportedFrame frame = hp::readFrameExport(dimDir);
  EXPECT_EQ(frame.skinColor, glm::vec3(0.2f, 0.3f, 0.4f));
  std::size_t skin = 0;
  for (const glm::vec3& a : frame.headAlbedo) skin += a == glm::vec3(0.2f, 0.3f, 0.4f) ? 1 : 0;
  EXPECT_GT(skin, frame.headAlbedo.size() / 2);
  EXPECT_EQ(hp::readFrameExport(redDir).skinColor, glm::vec3(0.8f, 0.3f, 0.4f));

  const hp::LinearImage dim = hp::readPfm(dimDir / hp::FrameExportFiles::realtime);
  const hp::LinearImage red = hp::readPfm(redDir / hp::FrameExportFiles::realtime);
  ASSERT_EQ(dim.channels, 3u);
  ASSERT_EQ(red.channels, 3u);
  ASSERT_EQ(dim.width, 64u);
  ASSERT_EQ(dim.height, 48u);
  ASSERT_EQ(red.width, dim.width);
  ASSERT_EQ(red.height, dim.height);
  std::size_t skinPixels = 0;
  glm::dvec3 dimSum(0.0), redSum(0.0);
  for (std::uint32_t y = 0; y < dim.height; ++y)
    for (std::uint32_t x = 0; x < dim.width; ++x) {
      const glm::dvec3 d(dim.at(x, y, 0), dim.at(x, y, 1), dim.at(x, y, 2));
      const glm::dvec3 r(red.at(x, y, 0), red.at(x, y, 1), red.at(x, y, 2));
      if (!(d.r > 0.0 && r.r >= 2.0 * d.r)) continue;
      ++skinPixels;
      dimSum += d;
      redSum += r;
    }
  // From the front the skin fills about a quarter of the frame (docs/images/head_front.png): at least 5%.
  EXPECT_GT(skinPixels, std::size_t(dim.width) * dim.height / 20) << "pixels whose red at least doubled";
  ASSERT_GT(skinPixels, 0u);
  // Mostly skin-only pixels (4x); never more than the albedo's ratio.
  EXPECT_GT(redSum.r, 3.0 * dimSum.r) << redSum.r << " against " << dimSum.r;
  EXPECT_LT(redSum.r, 4.05 * dimSum.r) << redSum.r << " against " << dimSum.r;
  // Green and blue did not change where the red rose (2%: hair shadows on the skin are the same frame).
  EXPECT_NEAR(redSum.g, dimSum.g, 0.02 * dimSum.g);
  EXPECT_NEAR(redSum.b, dimSum.b, 0.02 * dimSum.b);
}
