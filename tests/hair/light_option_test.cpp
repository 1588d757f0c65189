// `--light SPEC` (samples/tools/host/light_option.h): each type with its keys and defaults, and every refusal
// naming the key and the value.
#include <gtest/gtest.h>

#include <cmath>

#include "samples/tools/host/light_option.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
const glm::vec3 kCameraTarget{0.0f, -0.08f, 0.0f};

LightSpec parseSpec(const std::string& spec) { return parseLightOption(spec, kCameraTarget); }
std::string specError(const std::string& spec) {
  return test::errorOf([&] { parseSpec(spec); });
}

TEST(LightOption, DirectionalTakesDirectionColourAndIntensity) {
  const LightSpec l = parseSpec("directional:dir=0,0,2:color=1,0.9,0.8:intensity=3.5");
  EXPECT_EQ(l.type, LightSpec::Type::Directional);
  EXPECT_EQ(l.direction, glm::vec3(0, 0, 1));  // normalised
  EXPECT_EQ(l.color, glm::vec3(1, 0.9f, 0.8f));
  EXPECT_EQ(l.intensity, 3.5f);
  EXPECT_TRUE(l.shadows);
  const LightSpec sun = parseSpec("directional");  // every key optional: the default sun
  EXPECT_EQ(sun.direction, LightSpec{}.direction);
  EXPECT_EQ(sun.intensity, LightSpec{}.intensity);
}

TEST(LightOption, SpotAimsAtItsTargetOrTheCameraTarget) {
  const LightSpec s = parseSpec("spot:pos=0,3,4:target=0,0,0:cone=35:range=0.8");
  EXPECT_EQ(s.type, LightSpec::Type::Spot);
  EXPECT_EQ(s.position, glm::vec3(0, 3, 4));
  EXPECT_NEAR(glm::distance(s.direction, glm::vec3(0, 0.6f, 0.8f)), 0.0f, 1e-6f);
  EXPECT_EQ(s.coneDeg, 35.0f);
  EXPECT_EQ(s.range, 0.8f);
  const LightSpec d = parseSpec("spot:pos=0,0.92,0");  // aimed at the camera target, default cone and range
  EXPECT_NEAR(glm::distance(d.direction, glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_EQ(d.coneDeg, 30.0f);
  EXPECT_EQ(d.range, 0.0f);
}

TEST(LightOption, PointTakesPositionRangeAndShadows) {
  const LightSpec p = parseSpec("point:pos=0.3,0.4,0.5:intensity=2:range=0.5:shadows=off");
  EXPECT_EQ(p.type, LightSpec::Type::Point);
  EXPECT_EQ(p.position, glm::vec3(0.3f, 0.4f, 0.5f));
  EXPECT_EQ(p.intensity, 2.0f);
  EXPECT_EQ(p.range, 0.5f);
  EXPECT_FALSE(p.shadows);
  EXPECT_TRUE(parseSpec("point:shadows=on:pos=1,1,1").shadows);  // keys in any order
}

TEST(LightOption, BadSpecsAreRefusedNamingTheKeyAndValue) {
  struct Case {
    const char* spec;
    const char* needle;
  };
  const Case cases[] = {
      {"", "the light type must be directional, spot or point, got ''"},
      {"area:pos=0,1,0", "got 'area'"},
      {"point", "a point light needs pos=X,Y,Z"},
      {"spot:cone=20", "a spot light needs pos=X,Y,Z"},
      {"point:pos=0,1", "pos=0,1: expected X,Y,Z"},
      {"point:pos=0,1,x", "pos=0,1,x: expected a number, got 'x'"},
      {"point:pos=0,1,1e60", "pos=0,1,1e60: must be a finite number"},
      {"directional:intensity=nan", "intensity=nan: must be a finite number"},
      {"directional:intensity=-1", "intensity=-1: must be >= 0"},
      {"directional:intensity=2x", "intensity=2x: expected a number"},
      {"directional:intensity=", "intensity=: expected a number"},
      {"directional:color=1,-0.5,1", "color=1,-0.5,1: components must be >= 0"},
      // Finite but past what the half-float radiance images hold: the lit hair came out black.
      {"directional:intensity=3e38:color=10,10,10", "light intensity x colour must be at most 10000, got Inf"},
      {"directional:intensity=2000:color=1,6,1", "light intensity x colour must be at most 10000, got 12000"},
      {"directional:dir=0,0,0", "dir=0,0,0: must be a non-zero vector"},
      {"directional:dir=1e30,1e30,1e30", "dir=1e30,1e30,1e30: components must be within +-10000"},  // was "non-zero"
      {"spot:pos=1e30,0,0", "pos=1e30,0,0: components must be within +-10000"},  // was "a unit vector"
      {"spot:pos=0,1,0:cone=0", "cone=0: must be in (0, 80] degrees"},
      {"spot:pos=0,1,0:cone=81", "cone=81: must be in (0, 80] degrees"},
      {"spot:pos=0,1,0:target=0,1,0", "target=0,1,0: must differ from pos"},
      {"spot:pos=0,-0.08,0", "pos=0,-0.08,0: must differ from the spot's target"},
      {"point:pos=0,1,0:range=-2", "range=-2: must be >= 0"},
      {"point:pos=0,1,0:shadows=maybe", "shadows=maybe: expected on or off"},
      {"point:pos=0,1,0:cone=20", "'cone' is not a key of a point light (its keys: pos, range, color, intensity, shadows)"},
      {"directional:pos=0,1,0", "'pos' is not a key of a directional light"},
      {"spot:pos=0,1,0:dir=0,1,0", "'dir' is not a key of a spot light"},
      {"point:pos=0,1,0:pos=1,1,1", "'pos' is given twice"},
      {"point:pos=0,1,0:range", "'range' is not KEY=VALUE"},
      {"point:pos=0,1,0::range=1", "'' is not KEY=VALUE"},
  };
  for (const Case& c : cases) {
    const std::string e = specError(c.spec);
    EXPECT_NE(e.find(c.needle), std::string::npos) << "'" << c.spec << "' -> " << e;
  }
}
}  // namespace
}  // namespace hp
