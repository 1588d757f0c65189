// The scene file's light section: a spot light (type, position, target, coneDeg, range) and every
// refusal naming the JSON path; LightSpec::makeSpot and validate.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
Scene parse(const std::string& json) { return parseScene(json, "scene.json", "/base"); }
std::string parseError(const std::string& json) {
  return test::errorOf([&] { parse(json); });
}

TEST(SceneLight, DefaultIsDirectional) {
  EXPECT_EQ(parse("{}").light.type, LightSpec::Type::Directional);
  EXPECT_EQ(parse(R"({"light": {"type": "directional", "direction": [0, 2, 0]}})").light.direction, glm::vec3(0, 1, 0));
}

TEST(SceneLight, SpotReadsPositionTargetConeAndRange) {
  const Scene s = parse(R"({"light": {"type": "spot", "position": [0, 3, 4], "target": [0, 0, 0],
                                      "coneDeg": 25, "range": 5, "intensity": 2}})");
  EXPECT_EQ(s.light.type, LightSpec::Type::Spot);
  EXPECT_EQ(s.light.position, glm::vec3(0, 3, 4));
  EXPECT_NEAR(glm::distance(s.light.direction, glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);  // toward the light
  EXPECT_EQ(s.light.coneDeg, 25.0f);
  EXPECT_EQ(s.light.range, 5.0f);
  EXPECT_EQ(s.light.intensity, 2.0f);
  const Scene d = parse(R"({"light": {"type": "spot", "position": [1, 0, 0]}})");  // target defaults to the origin
  EXPECT_EQ(d.light.direction, glm::vec3(1, 0, 0));
  EXPECT_EQ(d.light.coneDeg, 30.0f);
  EXPECT_EQ(d.light.range, 0.0f);
}

TEST(SceneLight, BadSpotValuesAreRefusedNamingThePath) {
  struct Case {
    const char* json;
    const char* needle;
  };
  const Case cases[] = {
      {R"({"light": {"type": "point"}})", "/light/type: expected \"directional\" or \"spot\""},
      {R"({"light": {"type": 3}})", "/light/type"},
      {R"({"light": {"type": "spot"}})", "/light/position: is required for a spot light"},
      {R"({"light": {"type": "spot", "position": [0, 1]}})", "/light/position"},
      {R"({"light": {"type": "spot", "position": "up"}})", "/light/position"},
      {R"({"light": {"type": "spot", "position": [1, 1, 1], "target": [1, 1, 1]}})", "/light/target: must differ"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "coneDeg": 0}})", "/light/coneDeg: must be in (0, 80]"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "coneDeg": 85}})", "/light/coneDeg: must be in (0, 80]"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "coneDeg": "wide"}})", "/light/coneDeg"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "range": -1}})", "/light/range: must be >= 0"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "direction": [0, 1, 0]}})", "/light/direction: a spot"},
      {R"({"light": {"type": "spot", "position": [0, 1, 0], "angle": 10}})", "/light/angle"},
      {R"({"light": {"position": [0, 1, 0]}})", "/light/position: is for a spot light only"},
      {R"({"light": {"coneDeg": 20}})", "/light/coneDeg: is for a spot light only"},
  };
  for (const Case& c : cases) {
    const std::string e = parseError(c.json);
    EXPECT_NE(e.find(std::string("scene.json: ") + c.needle), std::string::npos) << c.json << " -> " << e;
  }
}

TEST(SceneLight, MakeSpotAimsAndValidates) {
  const LightSpec l = LightSpec::makeSpot({0, 0, 2}, {0, 0, 0}, 20.0f);
  EXPECT_EQ(l.type, LightSpec::Type::Spot);
  EXPECT_EQ(l.direction, glm::vec3(0, 0, 1));
  EXPECT_NE(test::errorOf([] { LightSpec::makeSpot({0, 0, 0}, {0, 0, 0}, 20.0f); }).find("target"), std::string::npos);
  EXPECT_NE(test::errorOf([] { LightSpec::makeSpot({0, 0, 1}, {0, 0, 0}, 90.0f); }).find("coneDeg"), std::string::npos);
  EXPECT_NE(test::errorOf([] { LightSpec::makeSpot({NAN, 0, 1}, {0, 0, 0}, 20.0f); }).find("finite"), std::string::npos);
}
}  // namespace
}  // namespace hp
