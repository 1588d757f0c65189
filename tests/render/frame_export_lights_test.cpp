// The frame export's lights (docs/FRAME_EXPORT.md), on the host: version 2 writes "lights", a list of up to 8
// (directional, spot, point, each with its shadows switch) that reads back bit for bit; a version 1
// frame.json's single "light" still reads as one light; a bad or extra light is refused naming its place. The
// environment map travels beside them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"
#include "tests/support/cli_runner.h"
#include "tests/support/refusal.h"

using namespace hp;

namespace {
// The smallest valid export: one two-point strand, no head, a pinhole looking down -z.
ExportedFrame tinyFrame() {
  ExportedFrame f;
  f.camera = {{0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 35.0f, 8, 8};
  f.strands.strandCount = 1;
  f.strands.defaultSegments = 1;
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(0.1f, 0, 0)}) {
    f.strands.points.push_back(p);
    f.strands.thickness.push_back(0.0005f);
    f.strands.colors.push_back(f.hairAlbedo);
  }
  return f;
}

std::vector<LightSpec> threeLights() {
  LightSpec sun;
  sun.direction = glm::normalize(glm::vec3(0.1f, 0.7f, 0.3f));
  sun.color = {1.0f, 0.9f, 0.8f};
  LightSpec point = LightSpec::makePoint({0.3f, 0.4f, 0.5f}, 0.5f);
  point.intensity = 2.0f;
  point.shadows = false;
  LightSpec spot = LightSpec::makeSpot({0.3f, 0.4f, 0.6f}, {0.0f, -0.08f, 0.0f}, 35.0f);
  spot.range = 0.8f;
  return {sun, spot, point};
}

nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

void writeJson(const std::filesystem::path& path, const nlohmann::json& j) { std::ofstream(path) << j.dump(2); }

std::string readError(const std::filesystem::path& dir) {
  return test::refusalOf([&] { readFrameExport(dir); });
}
}  // namespace

TEST(FrameExportLights, AListOfLightsRoundTripsBitForBit) {
  const auto dir = test::freshTempPath("hairpipe_frame_export_lights");
  std::filesystem::create_directories(dir);
  ExportedFrame f = tinyFrame();
  f.lights = threeLights();
  writeFrameExport(dir, f);
  const nlohmann::json j = readJson(dir / FrameExportFiles::json);
  EXPECT_EQ(j["version"], 5);
  ASSERT_EQ(j["lights"].size(), 3u);
  EXPECT_EQ(j["lights"][2]["type"], "point");
  EXPECT_EQ(j["lights"][2]["shadows"], false);
  const ExportedFrame back = readFrameExport(dir);
  ASSERT_EQ(back.lights.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const LightSpec &a = f.lights[i], &b = back.lights[i];
    EXPECT_EQ(a.type, b.type) << i;
    EXPECT_EQ(a.direction, b.direction) << i;
    EXPECT_EQ(a.color, b.color) << i;
    EXPECT_EQ(a.intensity, b.intensity) << i;
    EXPECT_EQ(a.position, b.position) << i;
    EXPECT_EQ(a.coneDeg, b.coneDeg) << i;
    EXPECT_EQ(a.range, b.range) << i;
    EXPECT_EQ(a.shadows, b.shadows) << i;
  }
  f.lights.clear();  // no light at all: the sky alone
  writeFrameExport(dir, f);
  EXPECT_TRUE(readFrameExport(dir).lights.empty());
  // A new export whose strands cannot be written (a folder in their place) leaves no frame.json of the old one
  // to be read with whatever else is there.
  std::filesystem::remove(dir / FrameExportFiles::strands);
  std::filesystem::create_directories(dir / FrameExportFiles::strands / "blocked");
  EXPECT_NE(test::refusalOf([&] { writeFrameExport(dir, f); }), "(accepted)");
  EXPECT_FALSE(std::filesystem::exists(dir / FrameExportFiles::json));
  EXPECT_NE(readError(dir).find("frame.json"), std::string::npos) << readError(dir);
  std::filesystem::remove_all(dir);
}

// The environment map travels as environment.pfm beside frame.json, its intensity and rotation in the JSON;
// a map whose file is missing or holds a negative texel is refused naming "environment_map".
TEST(FrameExportLights, TheEnvironmentMapRoundTripsAndABadOneIsRefused) {
  const auto dir = test::freshTempPath("hairpipe_frame_export_environment");
  std::filesystem::create_directories(dir);
  ExportedFrame f = tinyFrame();
  auto map = std::make_shared<EnvironmentMap>(studioEnvironment(16, 8));
  map->intensity = 1.5;
  map->rotationDeg = 40.0;
  f.environmentMap = map;
  writeFrameExport(dir, f);
  const ExportedFrame back = readFrameExport(dir);
  ASSERT_TRUE(back.environmentMap);
  EXPECT_EQ(back.environmentMap->texels, map->texels);
  EXPECT_EQ(back.environmentMap->width, 16u);
  EXPECT_EQ(back.environmentMap->intensity, 1.5);
  EXPECT_EQ(back.environmentMap->rotationDeg, 40.0);
  LinearImage negative(2, 1, 3);
  negative.values[4] = -1.0f;
  writePfm(dir / FrameExportFiles::environment, negative);
  EXPECT_NE(readError(dir).find("environment_map"), std::string::npos) << readError(dir);
  std::filesystem::remove(dir / FrameExportFiles::environment);
  EXPECT_NE(readError(dir).find("environment.pfm"), std::string::npos) << readError(dir);
  f.environmentMap = nullptr;  // none: no key, no file
  writeFrameExport(dir, f);
  EXPECT_FALSE(readJson(dir / FrameExportFiles::json).contains("environment_map"));
  EXPECT_FALSE(readFrameExport(dir).environmentMap);
  std::filesystem::remove_all(dir);
}

TEST(FrameExportLights, AVersionOneExportsSingleLightReadsAsOneLight) {
  const auto dir = test::freshTempPath("hairpipe_frame_export_v1");
  std::filesystem::create_directories(dir);
  ExportedFrame f = tinyFrame();
  f.lights = {threeLights()[1]};
  writeFrameExport(dir, f);
  nlohmann::json j = readJson(dir / FrameExportFiles::json);
  nlohmann::json light = j["lights"][0];
  light.erase("shadows");  // version 1 had no switch
  j.erase("lights");
  j["light"] = light;
  j["version"] = 1;
  writeJson(dir / FrameExportFiles::json, j);
  const ExportedFrame back = readFrameExport(dir);
  ASSERT_EQ(back.lights.size(), 1u);
  EXPECT_EQ(back.lights[0].type, LightSpec::Type::Spot);
  EXPECT_EQ(back.lights[0].position, f.lights[0].position);
  EXPECT_EQ(back.lights[0].coneDeg, 35.0f);
  EXPECT_TRUE(back.lights[0].shadows);
  j["version"] = 2;  // version 2 has "lights", not "light"
  writeJson(dir / FrameExportFiles::json, j);
  EXPECT_NE(readError(dir).find("/lights: missing"), std::string::npos) << readError(dir);
  j["version"] = 6;
  writeJson(dir / FrameExportFiles::json, j);
  EXPECT_NE(readError(dir).find("version 1 to 5"), std::string::npos) << readError(dir);
  std::filesystem::remove_all(dir);
}

TEST(FrameExportLights, ABadOrExtraLightIsRefusedNamingItsPlace) {
  const auto dir = test::freshTempPath("hairpipe_frame_export_bad_lights");
  std::filesystem::create_directories(dir);
  ExportedFrame f = tinyFrame();
  f.lights = threeLights();
  writeFrameExport(dir, f);
  const nlohmann::json good = readJson(dir / FrameExportFiles::json);
  nlohmann::json j = good;
  j["lights"][1]["cone_deg"] = 90;
  writeJson(dir / FrameExportFiles::json, j);
  EXPECT_NE(readError(dir).find("frame.json: /lights/1: spot coneDeg must be in (0, 80]"), std::string::npos)
      << readError(dir);
  j = good;
  j["lights"][2]["type"] = "area";
  writeJson(dir / FrameExportFiles::json, j);
  EXPECT_NE(readError(dir).find("/lights/2/type"), std::string::npos) << readError(dir);
  j = good;
  for (int i = 0; i < 6; ++i) j["lights"].push_back(good["lights"][0]);
  writeJson(dir / FrameExportFiles::json, j);
  EXPECT_NE(readError(dir).find("/lights: at most 8 lights, got 9"), std::string::npos) << readError(dir);
  std::filesystem::remove_all(dir);
}
