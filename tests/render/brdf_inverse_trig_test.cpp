// The shader's own asin/acos (shaders/shared/marschner.h, compiled here as C++ in float) against the
// double-precision library: they replace driver built-ins that lavapipe evaluates to only ~1e-4 rad.
#include <gtest/gtest.h>

#include <cmath>

#include "shaders/shared/marschner.h"

TEST(BrdfInverseTrig, AsinAndAcosAreAccurateToAFewUlpInFloat) {
  double worstAsin = 0, worstAcos = 0;
  const int n = 200'001;
  for (int i = 0; i < n; ++i) {
    const float x = -1.0f + 2.0f * float(i) / float(n - 1);
    const double as = std::asin(double(x)), ac = std::acos(double(x));
    worstAsin = std::max(worstAsin, std::abs(double(hp::gpu::marschnerAsin(x)) - as) / std::max(std::abs(as), 1e-30));
    worstAcos = std::max(worstAcos, std::abs(double(hp::gpu::marschnerAcos(x)) - ac) / std::max(std::abs(ac), 1e-30));
  }
  EXPECT_LT(worstAsin, 5e-7) << "relative";
  EXPECT_LT(worstAcos, 5e-7) << "relative";
  EXPECT_EQ(hp::gpu::marschnerAsin(0.0f), 0.0f);
  EXPECT_EQ(hp::gpu::marschnerAcos(1.0f), 0.0f);
  EXPECT_NEAR(hp::gpu::marschnerAsin(1.0f), std::acos(0.0), 2e-7);
  EXPECT_NEAR(hp::gpu::marschnerAcos(-1.0f), std::acos(-1.0), 3e-7);
}
