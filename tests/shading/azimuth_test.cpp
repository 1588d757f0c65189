// Root finding of the cubic exit azimuth, and the exact TRT caustic form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "engine/core/shading/azimuth.h"
#include "engine/core/shading/math_constants.h"

using namespace hp::shading;
using hp::shading::kPi;  // one pi for every shading file (unity builds)

TEST(Azimuth, DepressedCubicFindsAllRealRoots) {
  std::array<double, 3> r{};
  ASSERT_EQ(solveDepressedCubic(-7.0, 6.0, r), 3);  // (x-1)(x-2)(x+3)
  EXPECT_NEAR(r[0], -3.0, 1e-12);
  EXPECT_NEAR(r[1], 1.0, 1e-12);
  EXPECT_NEAR(r[2], 2.0, 1e-12);
  ASSERT_EQ(solveDepressedCubic(1.0, -2.0, r), 1);  // x^3 + x - 2 = (x-1)(x^2+x+2)
  EXPECT_NEAR(r[0], 1.0, 1e-12);
}

TEST(Azimuth, RRootIsMinusHalfPhi) {
  for (double phi : {0.0, 0.3, 1.7, 3.0}) {
    AzimuthRoots roots = azimuthRoots(0, 1.6, phi);
    ASSERT_GE(roots.count, 1u);
    EXPECT_NEAR(roots.gamma[0], -phi / 2, 1e-14);
  }
}

TEST(Azimuth, EveryRootSolvesPhiModTwoPi) {
  for (int p = 0; p <= 2; ++p)
    for (double etaP : {1.2, 1.55, 1.9, 2.5, 4.0})
      for (double phi = 0.0; phi <= kPi; phi += 0.05) {
        AzimuthRoots roots = azimuthRoots(p, etaP, phi);
        for (std::size_t i = 0; i < roots.count; ++i) {
          double g = roots.gamma[i];
          EXPECT_LE(std::abs(g), kPi / 2 + 1e-12);
          double r = std::remainder(phiCubic(p, g, etaP) - phi, 2 * kPi);
          EXPECT_NEAR(r, 0.0, 1e-9) << p << " " << etaP << " " << phi;
        }
      }
}

TEST(Azimuth, RootCountMatchesBruteForceSignChanges) {
  // Count crossings of Phi(gamma) - phi - 2 pi k on a fine grid and compare with the solver.
  for (int p = 1; p <= 2; ++p)
    for (double etaP : {1.3, 1.55, 1.8, 3.0})
      for (double phi = 0.01; phi < kPi; phi += 0.07) {
        int crossings = 0;
        const int n = 20000;
        for (int k = -4; k <= 4; ++k) {
          double prev = phiCubic(p, -kPi / 2, etaP) - phi - 2 * kPi * k;
          for (int i = 1; i <= n; ++i) {
            double g = -kPi / 2 + kPi * i / n;
            double cur = phiCubic(p, g, etaP) - phi - 2 * kPi * k;
            if ((prev < 0) != (cur < 0)) ++crossings;
            prev = cur;
          }
        }
        EXPECT_EQ(static_cast<int>(azimuthRoots(p, etaP, phi).count), crossings)
            << p << " " << etaP << " " << phi;
      }
}

TEST(Azimuth, ExactTrtCausticHasZeroSlopeAtHc) {
  for (double etaP : {1.2, 1.55, 1.9}) {
    double hc = std::sqrt((4 - etaP * etaP) / 3);
    double e = 1e-6;
    double slope = (phiExactTRT(hc + e, etaP) - phiExactTRT(hc - e, etaP)) / (2 * e);
    EXPECT_NEAR(slope, 0.0, 1e-6);
    double d2 = (phiExactTRT(hc + 1e-4, etaP) - 2 * phiExactTRT(hc, etaP) + phiExactTRT(hc - 1e-4, etaP)) / 1e-8;
    EXPECT_NEAR(d2PhiExactTRTdH2(hc, etaP), d2, 1e-4 * std::abs(d2) + 1e-6);
  }
}
