// Marschner's longitudinal shifts in direction space: for a fixed light, the R lobe's peak reflected
// inclination is turned toward the root (theta_r = 2 alpha_R - theta_i < -theta_i, alpha_R < 0) and
// TRT's toward the tip (theta_r = -3 alpha_R - theta_i). (Where the bands land in an image is tested in
// tests/render/highlight_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/shading/marschner_terms.h"

using namespace hp;

namespace {
// The theta_r in [-80, 80] deg maximising M_p for a light at thetaI (both in radians).
double peakThetaR(int p, double thetaI, const HairMaterial& m) {
  double best = 0.0, bestValue = -1.0;
  for (int k = -8000; k <= 8000; ++k) {
    const double thetaR = glm::radians(k * 0.01);
    const double value = shading::lobeM(p, 0.5 * (thetaI + thetaR), m);
    if (value > bestValue) bestValue = value, best = thetaR;
  }
  return best;
}
}  // namespace

TEST(LobeShift, RIsTurnedTowardTheRootAndTrtTowardTheTip) {
  HairMaterial m;
  ASSERT_LT(m.alphaR, 0.0);
  for (double thetaIDeg : {-30.0, 0.0, 25.0}) {
    const double thetaI = glm::radians(thetaIDeg);
    const double mirror = -thetaI;
    const double r = peakThetaR(0, thetaI, m), trt = peakThetaR(2, thetaI, m);
    EXPECT_NEAR(r, mirror + 2.0 * m.alphaR, glm::radians(0.02));
    EXPECT_NEAR(trt, mirror - 3.0 * m.alphaR, glm::radians(0.02));
    EXPECT_LT(r, mirror) << "R toward the root (negative theta is toward the root)";
    EXPECT_GT(trt, mirror) << "TRT toward the tip";
  }
}
