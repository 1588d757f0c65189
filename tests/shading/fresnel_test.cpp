// Fresnel term: known values, TIR, polarisation split.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/shading/fresnel.h"

using namespace hp::shading;

TEST(Fresnel, NormalIncidenceMatchesClosedForm) {
  for (double n : {1.33, 1.55, 2.0, 1.0 / 1.55}) {
    double r = (n - 1.0) / (n + 1.0);
    EXPECT_NEAR(fresnel(n, n, 0.0), r * r, 1e-15) << n;
  }
}

TEST(Fresnel, GrazingIncidenceReflectsEverything) { EXPECT_NEAR(fresnel(1.55, 1.55, M_PI / 2), 1.0, 1e-12); }

TEST(Fresnel, TotalInternalReflectionIsOne) {
  double n = 1.0 / 1.55;
  double critical = std::asin(n);
  EXPECT_EQ(fresnel(n, n, critical + 1e-3), 1.0);
  EXPECT_EQ(fresnel(n, n, 1.2), 1.0);
  EXPECT_LT(fresnel(n, n, critical - 1e-2), 1.0);
}

TEST(Fresnel, BrewsterAngleZeroesP) {
  double n = 1.55;
  EXPECT_NEAR(fresnelP(n, std::atan(n)), 0.0, 1e-15);
  EXPECT_GT(fresnelS(n, std::atan(n)), 0.05);
  EXPECT_NEAR(fresnel(n, n, std::atan(n)), 0.5 * fresnelS(n, std::atan(n)), 1e-15);
}

TEST(Fresnel, UsesN1ForSAndN2ForP) {
  EXPECT_DOUBLE_EQ(fresnel(1.4, 1.8, 0.6), 0.5 * (fresnelS(1.4, 0.6) + fresnelP(1.8, 0.6)));
  EXPECT_DOUBLE_EQ(fresnel(1.4, 1.8, -0.6), fresnel(1.4, 1.8, 0.6));
}
