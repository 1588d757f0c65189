// HairMaterial validation and the colour -> absorption conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/core/shading/material.h"
#include "engine/core/shading/material_color.h"

using hp::HairMaterial;

namespace {
std::string errorOf(const HairMaterial& m) {
  try {
    m.validate();
  } catch (const hp::Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Material, DefaultsAreValid) { EXPECT_NO_THROW(HairMaterial{}.validate()); }

TEST(Material, BadFieldsAreNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    void (*set)(HairMaterial&, double);
    double value;
    const char* field;
  };
  Case cases[] = {
      {[](HairMaterial& m, double v) { m.eta = v; }, 1.0, "eta"},
      {[](HairMaterial& m, double v) { m.eta = v; }, 3.1, "eta"},
      {[](HairMaterial& m, double v) { m.eta = v; }, nan, "eta"},
      {[](HairMaterial& m, double v) { m.absorption.g = v; }, -0.1, "absorption[g]"},
      {[](HairMaterial& m, double v) { m.absorption.b = v; }, inf, "absorption[b]"},
      {[](HairMaterial& m, double v) { m.alphaR = v; }, glm::radians(31.0), "alphaR"},
      {[](HairMaterial& m, double v) { m.alphaR = v; }, glm::radians(-31.0), "alphaR"},
      {[](HairMaterial& m, double v) { m.betaR = v; }, 0.0, "betaR"},
      {[](HairMaterial& m, double v) { m.betaR = v; }, glm::radians(46.0), "betaR"},
      {[](HairMaterial& m, double v) { m.kG = v; }, -1.0, "kG"},
      {[](HairMaterial& m, double v) { m.wc = v; }, 0.0, "wc"},
      {[](HairMaterial& m, double v) { m.dEta = v; }, 0.0, "dEta"},
      {[](HairMaterial& m, double v) { m.dhM = v; }, -0.5, "dhM"},
      {[](HairMaterial& m, double v) { m.dhM = v; }, nan, "dhM"},
      {[](HairMaterial& m, double v) { m.betaN = v; }, 0.01, "betaN"},
      {[](HairMaterial& m, double v) { m.betaN = v; }, 1.0, "betaN"},
      {[](HairMaterial& m, double v) { m.tiltVariation = v; }, -0.01, "tiltVariation"},
      {[](HairMaterial& m, double v) { m.tiltVariation = v; }, glm::radians(11.0), "tiltVariation"},
      {[](HairMaterial& m, double v) { m.tiltVariation = v; }, nan, "tiltVariation"},
      {[](HairMaterial& m, double v) { m.roughnessVariation = v; }, -0.01, "roughnessVariation"},
      {[](HairMaterial& m, double v) { m.roughnessVariation = v; }, 0.26, "roughnessVariation"},
      {[](HairMaterial& m, double v) { m.roughnessVariation = v; }, 1e-40, "roughnessVariation"},
      {[](HairMaterial& m, double v) { m.roughnessVariation = v; }, nan, "roughnessVariation"},
  };
  for (const Case& c : cases) {
    HairMaterial m;
    c.set(m, c.value);
    std::string err = errorOf(m);
    EXPECT_NE(err.find(std::string("HairMaterial.") + c.field + " "), std::string::npos) << err;
  }
}

TEST(Material, ColorRoundTripsAndMatchesDefaultBrown) {
  glm::dvec3 c = hp::colorFromAbsorption(HairMaterial{}.absorption);
  glm::dvec3 s = hp::absorptionFromColor(c);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s[k], HairMaterial{}.absorption[k], 1e-14);
  EXPECT_NEAR(c.r, std::exp(-1.1), 1e-14);
  EXPECT_EQ(hp::absorptionFromColor({1, 1, 1}), glm::dvec3(0.0));
}

TEST(Material, BadColorIsNamed) {
  EXPECT_THROW(hp::absorptionFromColor({0.5, 0.0, 0.5}), hp::Error);
  try {
    hp::absorptionFromColor({0.5, 0.5, 1.5});
    ADD_FAILURE() << "a colour component above 1 was accepted";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("color[b]"), std::string::npos) << e.what();
  }
}
