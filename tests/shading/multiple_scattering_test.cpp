// The multiple-scattering tables of the physical fibre model (engine/shading/multiple_scattering.h): the
// azimuthal means add up to the white furnace (M integrates to 1), the forward albedo agrees with a
// brute-force 2D quadrature of the exact S over the far half of the azimuths and never exceeds the
// furnace, and absorption orders it red > green > blue.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/error.h"
#include "engine/shading/furnace.h"
#include "engine/shading/material_color.h"
#include "engine/shading/math_constants.h"
#include "engine/shading/multiple_scattering.h"
#include "engine/shading/physical.h"
#include "engine/shading/quadrature.h"

using namespace hp;

namespace {
constexpr int kEntries = 9;

double sineOf(int k) { return std::clamp(-1.0 + 2.0 * k / (kEntries - 1), -kEdgeSine, kEdgeSine); }

// int over |phi| in [pi/2, pi] and theta_i of S cos^2 theta_i: the furnace restricted to forward light.
glm::dvec3 bruteForceForward(double sinTheta, const HairMaterial& m) {
  glm::dvec3 sum(0.0);
  shading::gaussLegendre(-0.5 * shading::kPi, 0.5 * shading::kPi, 24, [&](double ti, double wt) {
    const double c = std::cos(ti);
    shading::gaussLegendre(0.5 * shading::kPi, shading::kPi, 8, [&](double phi, double wp) {
      sum += 2.0 * wt * wp * c * c * physicalS(std::sin(ti), sinTheta, std::cos(phi), m);
    });
  });
  return sum;
}
}  // namespace

TEST(MultipleScattering, AzimuthalMeansAddUpToTheWhiteFurnace) {
  for (const glm::dvec3 absorption : {glm::dvec3(0.0), HairMaterial{}.absorption}) {
    HairMaterial m;
    m.absorption = absorption;
    const MultipleScatteringTables t = multipleScatteringTables(m, kEntries);
    for (int k = 0; k < kEntries; ++k) {
      const glm::dvec3 means = 2.0 * shading::kPi * (glm::dvec3(t.meanR[k]) + t.meanTT[k] + t.meanTRT[k]);
      const glm::dvec3 furnace = whiteFurnace(FibreModel::Physical, sineOf(k), m);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(means[c], furnace[c], 2e-3) << "entry " << k << " channel " << c;
    }
  }
}

TEST(MultipleScattering, ForwardAlbedoMatchesABruteForceQuadratureAndStaysUnderTheFurnace) {
  const HairMaterial brown;
  const MultipleScatteringTables t = multipleScatteringTables(brown, kEntries);
  for (int k : {2, 4}) {  // -0.5 and 0 (the table is even in theta); the ends are too peaked for the panels
    const glm::dvec3 brute = bruteForceForward(sineOf(k), brown);
    const glm::dvec3 furnace = whiteFurnace(FibreModel::Physical, sineOf(k), brown);
    std::printf("sin theta %+.2f: a_f %.4f %.4f %.4f (brute force %.4f %.4f %.4f), furnace %.4f %.4f %.4f\n",
                sineOf(k), t.forwardAlbedo[k].r, t.forwardAlbedo[k].g, t.forwardAlbedo[k].b, brute.r, brute.g,
                brute.b, furnace.r, furnace.g, furnace.b);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(t.forwardAlbedo[k][c], brute[c], 0.01 * brute[c] + 1e-4) << "entry " << k << " channel " << c;
      EXPECT_GT(t.forwardAlbedo[k][c], 0.0);
      EXPECT_LT(t.forwardAlbedo[k][c], furnace[c]);
    }
    EXPECT_GT(t.forwardAlbedo[k].r, t.forwardAlbedo[k].g);  // brown absorbs blue most
    EXPECT_GT(t.forwardAlbedo[k].g, t.forwardAlbedo[k].b);
  }
}

TEST(MultipleScattering, ForwardAndBackAlbedoAddUpToTheWhiteFurnace) {
  const HairMaterial brown;
  const MultipleScatteringTables t = multipleScatteringTables(brown, kEntries);
  for (int k = 0; k < kEntries; ++k) {
    const glm::dvec3 furnace = whiteFurnace(FibreModel::Physical, sineOf(k), brown);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(t.forwardAlbedo[k][c] + t.backAlbedo[k][c], furnace[c], 2e-3) << "entry " << k << " channel " << c;
      EXPECT_GT(t.backAlbedo[k][c], 0.0);
    }
  }
}

// Zinke's local back-scattering: tiny for dark hair, a large share of the light for light hair (the
// series a_f^2 / (1 - a_f^2) grows fast as a_f -> 1), never more than the light a fibre returns at all.
TEST(MultipleScattering, BackScatteringGrowsWithLighterHairAndStaysUnderTheFurnace) {
  HairMaterial brown, blonde, white;
  blonde.absorption = absorptionFromColor(glm::dvec3(0.8, 0.65, 0.45));
  white.absorption = glm::dvec3(0.0);
  const int mid = kEntries / 2;
  double previous = 0.0;
  for (const HairMaterial* m : {&brown, &blonde, &white}) {
    const MultipleScatteringTables t = multipleScatteringTables(*m, kEntries);
    const glm::dvec3 A = t.backScatter[mid], af = t.forwardAlbedo[mid], ab = t.backAlbedo[mid];
    std::printf("a_f %.3f %.3f %.3f  a_b %.3f %.3f %.3f  A_b %.4f %.4f %.4f  shift %.1f deg  width %.1f deg\n",
                af.r, af.g, af.b, ab.r, ab.g, ab.b, A.r, A.g, A.b, glm::degrees(t.backShift[mid]),
                glm::degrees(t.backWidth[mid]));
    EXPECT_GT(A.g, previous);
    previous = A.g;
    for (int c = 0; c < 3; ++c) EXPECT_LT(A[c], 1.0);
  }
}

TEST(MultipleScattering, BackLobeIsCentredWithoutACuticleTilt) {
  HairMaterial m;
  m.alphaR = 0.0;
  const MultipleScatteringTables t = multipleScatteringTables(m, kEntries);
  for (int k = 0; k < kEntries; ++k) {
    EXPECT_NEAR(t.backShift[k], 0.0, 1e-12);
    EXPECT_GT(t.backWidth[k], 0.0);
    EXPECT_GE(t.backNorm[k], 1.0);  // the cos theta_r weight only takes away
  }
}

TEST(MultipleScattering, RefusesABadTableSize) {
  EXPECT_THROW(multipleScatteringTables(HairMaterial{}, 1), Error);
  EXPECT_THROW(multipleScatteringTables(HairMaterial{}, 5000), Error);
}
