// The scene file's lights: "light" (one) and "lights" (a list of up to 8: directional, spot and point lights,
// each with a shadows switch), every refusal naming the JSON path (the list's index among it);
// LightSpec::makeSpot and validate; validateLights and shadowSlotsFor.
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

// The one light "light" gives.
LightSpec only(const Scene& s) {
  EXPECT_EQ(s.lights.size(), 1u);
  return s.lights.empty() ? LightSpec{} : s.lights[0];
}

TEST(SceneLight, DefaultIsOneDirectionalSunCastingShadows) {
  const Scene s = parse("{}");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].type, LightSpec::Type::Directional);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_EQ(only(parse(R"({"light": {"type": "directional", "direction": [0, 2, 0]}})")).direction, glm::vec3(0, 1, 0));
}

TEST(SceneLight, SpotReadsPositionTargetConeAndRange) {
  const LightSpec s = only(parse(R"({"light": {"type": "spot", "position": [0, 3, 4], "target": [0, 0, 0],
                                                "coneDeg": 25, "range": 5, "intensity": 2}})"));
  EXPECT_EQ(s.type, LightSpec::Type::Spot);
  EXPECT_EQ(s.position, glm::vec3(0, 3, 4));
  EXPECT_NEAR(glm::distance(s.direction, glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);  // toward the light
  EXPECT_EQ(s.coneDeg, 25.0f);
  EXPECT_EQ(s.range, 5.0f);
  EXPECT_EQ(s.intensity, 2.0f);
  const LightSpec d = only(parse(R"({"light": {"type": "spot", "position": [1, 0, 0]}})"));  // target defaults to the origin
  EXPECT_EQ(d.direction, glm::vec3(1, 0, 0));
  EXPECT_EQ(d.coneDeg, 30.0f);
  EXPECT_EQ(d.range, 0.0f);
}

TEST(SceneLight, TheOneLightMayBeAPointLightWithoutShadows) {
  const LightSpec p = only(parse(R"({"light": {"type": "point", "position": [0, 1, 2], "range": 0.4, "shadows": false}})"));
  EXPECT_EQ(p.type, LightSpec::Type::Point);
  EXPECT_EQ(p.position, glm::vec3(0, 1, 2));
  EXPECT_EQ(p.range, 0.4f);
  EXPECT_FALSE(p.shadows);
}

TEST(SceneLight, LightsListReadsEveryTypeInOrder) {
  const Scene s = parse(R"({"lights": [
      {"type": "directional", "direction": [0, 0, 3], "color": [1, 0.9, 0.8], "intensity": 2},
      {"type": "spot", "position": [0, 3, 4], "coneDeg": 40, "range": 2},
      {"type": "point", "position": [0.3, 0.4, 0.5], "range": 0.5, "intensity": 1.5, "shadows": false}]})");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightSpec::Type::Directional);
  EXPECT_EQ(s.lights[0].direction, glm::vec3(0, 0, 1));
  EXPECT_EQ(s.lights[0].color, glm::vec3(1, 0.9f, 0.8f));
  EXPECT_EQ(s.lights[0].intensity, 2.0f);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_EQ(s.lights[1].type, LightSpec::Type::Spot);
  EXPECT_NEAR(glm::distance(s.lights[1].direction, glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);
  EXPECT_EQ(s.lights[1].coneDeg, 40.0f);
  EXPECT_EQ(s.lights[1].range, 2.0f);
  EXPECT_EQ(s.lights[2].type, LightSpec::Type::Point);
  EXPECT_EQ(s.lights[2].position, glm::vec3(0.3f, 0.4f, 0.5f));
  EXPECT_EQ(s.lights[2].range, 0.5f);
  EXPECT_EQ(s.lights[2].intensity, 1.5f);
  EXPECT_FALSE(s.lights[2].shadows);
  EXPECT_NO_THROW(validateLights(s.lights));
  EXPECT_EQ(shadowSlotsFor(s.lights), 2u);
}

TEST(SceneLight, AnEmptyListHasNoLightAndEightAreTheMost) {
  EXPECT_TRUE(parse(R"({"lights": []})").lights.empty());
  std::string eight = R"({"lights": [)", nine;
  for (int i = 0; i < 8; ++i) eight += std::string(i ? "," : "") + R"({"type": "point", "position": [0, 1, 0]})";
  nine = eight + R"(, {}]})";
  eight += "]}";
  EXPECT_EQ(parse(eight).lights.size(), 8u);
  EXPECT_NE(parseError(nine).find("scene.json: /lights: at most 8 lights, got 9"), std::string::npos) << parseError(nine);
}

TEST(SceneLight, LightAndLightsTogetherAreRefusedNamingBoth) {
  const std::string e = parseError(R"({"light": {"intensity": 1}, "lights": [{"intensity": 2}]})");
  EXPECT_NE(e.find("scene.json: /lights: give either \"light\" (one light) or \"lights\""), std::string::npos) << e;
}

TEST(SceneLight, ABadLightInTheListIsNamedByItsIndex) {
  struct Case {
    const char* json;
    const char* needle;
  };
  const Case cases[] = {
      {R"({"lights": [{}, {}, {"type": "spot", "position": [0, 1, 0], "coneDeg": 90}]})", "/lights/2/coneDeg: must be in (0, 80]"},
      {R"({"lights": [{}, {"type": "point"}]})", "/lights/1/position: is required for a point light"},
      {R"({"lights": [{"type": "point", "position": [0, 1, 0], "direction": [0, 1, 0]}]})", "/lights/0/direction: a point light"},
      {R"({"lights": [{"type": "point", "position": [0, 1, 0], "coneDeg": 20}]})", "/lights/0/coneDeg: is for a spot light only"},
      {R"({"lights": [{}, {"intensity": -1}]})", "/lights/1/intensity: must be >= 0"},
      {R"({"lights": [{"shadows": "yes"}]})", "/lights/0/shadows: expected true or false"},
      {R"({"lights": [{"type": "area"}]})", "/lights/0/type: expected \"directional\", \"spot\" or \"point\""},
      {R"({"lights": [{"power": 3}]})", "/lights/0/power: unknown key"},
      {R"({"lights": [3]})", "/lights/0: expected an object, got number"},
      {R"({"lights": {"type": "point"}})", "/lights: expected an array"},
  };
  for (const Case& c : cases) {
    const std::string e = parseError(c.json);
    EXPECT_NE(e.find(std::string("scene.json: ") + c.needle), std::string::npos) << c.json << " -> " << e;
  }
}

TEST(SceneLight, ValidateLightsNamesTheIndexAndTheLimit) {
  std::vector<LightSpec> lights(3);
  lights[2].type = LightSpec::Type::Spot;
  lights[2].coneDeg = 90.0f;
  EXPECT_NE(test::errorOf([&] { validateLights(lights); }).find("lights[2]: spot coneDeg must be in (0, 80]"),
            std::string::npos);
  EXPECT_NO_THROW(validateLights({}));
  const std::vector<LightSpec> nine(9);
  EXPECT_NE(test::errorOf([&] { validateLights(nine); }).find("at most 8 lights, got 9"), std::string::npos);
}

TEST(SceneLight, ShadowSlotsCountTheCastersWithinOneToFour) {
  std::vector<LightSpec> lights(6);
  EXPECT_EQ(shadowSlotsFor(lights), 4u);
  for (LightSpec& l : lights) l.shadows = false;
  EXPECT_EQ(shadowSlotsFor(lights), 1u);  // the settings' minimum: a slot no light uses
  lights[3].shadows = lights[5].shadows = true;
  EXPECT_EQ(shadowSlotsFor(lights), 2u);
  EXPECT_EQ(shadowSlotsFor({}), 1u);
}

TEST(SceneLight, BadSpotValuesAreRefusedNamingThePath) {
  struct Case {
    const char* json;
    const char* needle;
  };
  const Case cases[] = {
      {R"({"light": {"type": "area"}})", "/light/type: expected \"directional\", \"spot\" or \"point\""},
      {R"({"light": {"type": "point"}})", "/light/position: is required for a point light"},
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
      {R"({"light": {"position": [0, 1, 0]}})", "/light/position: is for a spot or point light only"},
      {R"({"light": {"range": 1}})", "/light/range: is for a spot or point light only"},
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
