// `hairpipe reference --frame DIR` and `hairpipe compare` on a tiny synthetic export (no device): the
// reference writes a PFM of the frame's size and a PNG through the render command's display curve,
// compare measures an image against itself as identical, and bad options exit 1 naming the problem
// without writing anything. (The real-time frame against the reference: tests/render/frame_export_test.cpp.)
#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include <nlohmann/json.hpp>

#include "engine/core/hair/input_file.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

namespace {
// A Lambertian square facing the camera with one strand across it, lit by the sun.
// `name`: the folder under the temp directory, one per test (CTest runs them in parallel).
// The square covers the frame's height. `head` false: a hair-only frame, whose head.obj holds no vertex and no face.
std::filesystem::path writeTinyExport(const std::string& name, bool head = true) {
  const auto dir = freshTempPath(name);
  std::filesystem::create_directories(dir);
  hp::ExportedFrame f;
  f.camera = {{0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 30.0f, 12, 8};
  f.environment = 0.1f;
  f.background = {0.05f, 0.06f, 0.07f};
  for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    if (!head) break;
    f.headPositions.emplace_back(c.x, c.y, 0.0f);
    f.headNormals.emplace_back(0, 0, 1);
    f.headAlbedo.emplace_back(0.6f, 0.45f, 0.35f);
  }
  if (head) f.headIndices = {0, 1, 2, 0, 2, 3};
  f.strands.strandCount = 1;
  f.strands.defaultSegments = 2;
  f.strands.points = {{-0.5f, -0.2f, 0.1f}, {0.0f, 0.0f, 0.15f}, {0.5f, 0.2f, 0.1f}};
  f.strands.thickness = {0.05f, 0.05f, 0.04f};
  f.strands.colors.assign(3, f.hairAlbedo);
  hp::writeFrameExport(dir, f);
  return dir;
}
}  // namespace

TEST(CliReference, TracesAnExportedFrameToPfmAndPng) {
  const auto dir = writeTinyExport("hairpipe_cli_reference_frame_1");
  const auto pfm = freshTempPath("hairpipe_cli_reference.pfm"), png = freshTempPath("hairpipe_cli_reference.png");
  auto r = runCli({"reference", "--frame", dir.string(), "--spp", "4", "--bounces", "2", "--out", pfm.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("tiles"), std::string::npos) << "no progress on stderr: " << r.err;
  const hp::LinearImage image = hp::readPfm(pfm);
  EXPECT_EQ(image.width, 12u);
  EXPECT_EQ(image.height, 8u);
  r = runCli({"reference", "--frame", dir.string(), "--spp", "4", "--bounces", "2", "--quiet", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(hp::readPngRgba(png).pixels, hp::displayRgba8(image, 1.0f)) << "the PNG is not the PFM tonemapped";

  r = runCli({"compare", "--image", pfm.string(), "--reference", pfm.string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json same = nlohmann::json::parse(r.out);  // an image against itself: exactly identical
  EXPECT_EQ(same.at("luminance_ratio").get<double>(), 1.0) << r.out;
  EXPECT_EQ(same.at("ssim").get<double>(), 1.0) << r.out;
  std::filesystem::remove_all(dir);
  std::filesystem::remove(pfm);
  std::filesystem::remove(png);
}

// render --hair-only --export-frame writes an empty head.obj: the reference traces the hair alone (a pixel
// on the square, off the strand, shows the background), and a head.obj with vertices but no face is still
// refused.
TEST(CliReference, AHairOnlyFrameTracesWithoutAHead) {
  const auto withHead = writeTinyExport("hairpipe_cli_reference_frame_head", true);
  const auto hairOnly = writeTinyExport("hairpipe_cli_reference_frame_hair_only", false);
  const auto pfm = freshTempPath("hairpipe_cli_reference_hair_only.pfm");
  const auto onSquare = [&](const std::filesystem::path& dir) {
    const auto r = runCli({"reference", "--frame", dir.string(), "--spp", "4", "--bounces", "2", "--quiet",
                           "--out", pfm.string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    hp::LinearImage image = hp::readPfm(pfm);
    return glm::vec3(image.at(2, 1, 0), image.at(2, 1, 1), image.at(2, 1, 2));  // on the square, off the strand
  };
  EXPECT_GT(onSquare(withHead).r, 0.1f);  // the lit square
  EXPECT_EQ(onSquare(hairOnly), glm::vec3(0.05f, 0.06f, 0.07f));
  std::ofstream(hairOnly / "head.obj") << "v 0 0 0 0.5 0.5 0.5\nvn 0 0 1\n";
  expectRefused({"reference", "--frame", hairOnly.string(), "--out", pfm.string()}, {{{}, "vertices but no triangles"}});
  std::filesystem::remove_all(withHead);
  std::filesystem::remove_all(hairOnly);
  std::filesystem::remove(pfm);
}

// Every value of an export is checked on read: out-of-range colours, radiances, wrap and lookup-table mode in
// frame.json, a number past float range, and head.obj albedos are refused naming the file and the value.
TEST(CliReference, ExportValuesOutOfRangeAreRefusedByName) {
  const auto dir = writeTinyExport("hairpipe_cli_reference_frame_values");
  const auto out = freshTempPath("hairpipe_cli_reference_values.pfm");
  const std::string json = hp::readInputText(dir / "frame.json", 1 << 20), obj = hp::readInputText(dir / "head.obj", 1 << 20);
  const auto edited = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = nlohmann::json::parse(json);
    edit(j);
    std::ofstream(dir / "frame.json") << j.dump(2);
  };
  const std::vector<std::pair<std::function<void(nlohmann::json&)>, std::string>> cases = {
      {[](nlohmann::json& j) { j["background_radiance"] = {-1.0, 0.0, 0.0}; }, "background_radiance"},
      {[](nlohmann::json& j) { j["skin"]["wrap"] = -100.0; }, "wrap"},
      {[](nlohmann::json& j) { j["skin"]["color"] = {0.5, 2.0, 0.5}; }, "color"},
      {[](nlohmann::json& j) { j["fibre"]["albedo"] = {-1.0, 0.5, 0.5}; }, "albedo"},
      {[](nlohmann::json& j) { j["fibre"]["lut_mode"] = "bogus\x01"; }, "lut_mode"},
      {[](nlohmann::json& j) { j["fibre"]["material"]["eta"] = 5.0; }, "frame.json: /fibre/material: HairMaterial"},
  };
  for (const auto& [edit, needle] : cases) {
    edited(edit);
    expectRefused({"reference", "--frame", dir.string(), "--out", out.string()}, {{{}, needle}}, out);
  }
  std::string overflow = json;
  const std::size_t at = overflow.find("\"exposure\": ");
  ASSERT_NE(at, std::string::npos);
  overflow.insert(at + 12, "1e999, \"x\": ");  // "exposure": 1e999, "x": <old value>
  std::ofstream(dir / "frame.json") << overflow;
  expectRefused({"reference", "--frame", dir.string(), "--out", out.string()}, {{{}, "frame.json: invalid JSON: number overflow"}}, out);
  std::ofstream(dir / "frame.json") << json;
  std::string badAlbedo = obj;
  const std::size_t v = badAlbedo.find("\nv ");
  ASSERT_NE(v, std::string::npos);
  badAlbedo.replace(v, 3, "\nv 0 0 0 -5 0 0\nv");  // an extra vertex first, its albedo -5
  std::ofstream(dir / "head.obj") << badAlbedo;
  expectRefused({"reference", "--frame", dir.string(), "--out", out.string()}, {{{}, "albedo must be in [0, 1]"}}, out);
  std::filesystem::remove_all(dir);
}

// A signal during the trace stops it between tiles: exit 1 naming the signal, and nothing in the output's
// folder (no image, no temporary file). SIGINT and SIGTERM alike.
TEST(CliReference, SignalsStopTheTraceAndWriteNothing) {
  const auto dir = writeTinyExport("hairpipe_cli_reference_frame_signal");
  for (const auto& [sig, name] : {std::pair{SIGINT, "SIGINT"}, std::pair{SIGTERM, "SIGTERM"}}) {
    const auto outDir = freshTempPath(std::string("hairpipe_cli_reference_signal_") + name);
    std::filesystem::remove_all(outDir);
    std::filesystem::create_directories(outDir);
    // 96 pixels x 1M samples: minutes of tracing, stopped within 1024 samples.
    hp::test::CliProcess child({"reference", "--frame", dir.string(), "--spp", "1048576", "--threads", "1",
                                "--out", (outDir / "ref.pfm").string()});
    std::this_thread::sleep_for(std::chrono::milliseconds(700));
    child.signal(sig);
    const auto r = child.wait();
    EXPECT_EQ(r.exitCode, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find(std::string("hairpipe: error: interrupted (") + name + ")"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("nothing written"), std::string::npos) << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(outDir)) << name << ": the output folder is not empty";
    std::filesystem::remove_all(outDir);
  }
  std::filesystem::remove_all(dir);
}

// A run whose host memory estimate exceeds the limit is refused up front, naming the estimate: for a
// frame export (images and strands), and for the scene options before the device renders anything.
TEST(CliReference, AHostMemoryEstimatePastTheLimitIsRefusedUpFront) {
  const auto dir = writeTinyExport("hairpipe_cli_reference_frame_memory");
  const auto out = freshTempPath("hairpipe_cli_reference_memory.pfm");
  expectRefused({"reference", "--out", out.string()}, {
      {{"--frame", dir.string(), "--max-memory", "0.000001"}, "reference at 12x8 needs about 0.0 GiB of host memory, more than the 0.0 GiB allowed"},
      {{"--width", "16384", "--height", "16384", "--max-memory", "2"}, "reference at 16384x16384 needs about 7.0 GiB"},
      {{"--frame", dir.string(), "--max-memory", "-1"}, "--max-memory must be in [0, 1e6] GiB"},
  }, out);
  std::filesystem::remove_all(dir);
}

TEST(CliReference, BadOptionsExitWithAMessageAndWriteNothing) {
  const auto dir = writeTinyExport("hairpipe_cli_reference_frame_2");
  const auto out = freshTempPath("hairpipe_cli_reference_bad.pfm");
  expectRefused({"reference", "--out", out.string()}, {
      {{"--frame", dir.string(), "--width", "64"}, "--width cannot be combined with --frame"},
      {{"--frame", dir.string(), "--spp", "0"}, "--spp"},
      {{"--frame", dir.string(), "--bounces", "0"}, "--bounces"},
      {{"--frame", (dir / "missing").string()}, "is not a frame export folder"},
  }, out);
  expectRefused({"reference", "--frame", dir.string()}, {
      {{"--out", freshTempPath("hairpipe_cli_reference_bad.jpg").string()}, ".pfm"},
  });
  std::filesystem::remove(dir / "head.obj");
  expectRefused({"reference", "--frame", dir.string(), "--out", out.string()}, {{{}, "head.obj"}}, out);
  std::filesystem::remove_all(dir);
}
