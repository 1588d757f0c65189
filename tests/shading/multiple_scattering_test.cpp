// The multiple-scattering tables of the physical fibre model (engine/core/shading/multiple_scattering.h): the
// azimuthal means add up to the white furnace (M integrates to 1), the forward albedo agrees with a
// brute-force 2D quadrature of the exact S over the far half of the azimuths and never exceeds the
// furnace, and absorption orders it red > green > blue.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "engine/core/error.h"
#include "engine/core/shading/furnace.h"
#include "engine/core/shading/lut.h"
#include "engine/core/shading/lut_sampler.h"
#include "engine/core/shading/material_color.h"
#include "engine/core/shading/math_constants.h"
#include "engine/core/shading/multiple_scattering.h"
#include "engine/core/shading/physical.h"
#include "engine/core/shading/quadrature.h"
#include "shaders/shared/marschner.h"

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

// Zinke's A_b against the paths of a layered hair counted one by one: fibres at depths 1, 2, ...; a crossing
// goes on (a_f) or turns back (a_b). A_1: down to depth d >= 2, back, up; A_3: down to d1, back, up to d2,
// back, down to d3, back, up (d2 < d1, d3). The table's closed forms must equal the sums.
TEST(MultipleScattering, BackScatteringIsTheSumOverThePathsOfALayeredHair) {
  HairMaterial blonde;
  blonde.absorption = absorptionFromColor(glm::dvec3(0.8, 0.65, 0.45));
  const MultipleScatteringTables t = multipleScatteringTables(blonde, kEntries);
  for (int k : {2, 4}) {
    for (int c = 0; c < 3; ++c) {
      const double af = t.forwardAlbedo[k][c], ab = t.backAlbedo[k][c];
      double once = 0.0, thrice = 0.0;
      for (int d = 2; d < 400; ++d) once += ab * std::pow(af, 2 * (d - 1));
      for (int d2 = 1; d2 < 120; ++d2)
        for (int d1 = d2 + 1; d1 < d2 + 120; ++d1)
          for (int d3 = d2 + 1; d3 < d2 + 120; ++d3)
            thrice += ab * ab * ab * std::pow(af, (d1 - 1) + (d1 - d2 - 1) + (d3 - d2 - 1) + (d3 - 1));
      EXPECT_NEAR(t.backScatter[k][c], once + thrice, 1e-6 * (once + thrice)) << "entry " << k << " channel " << c;
    }
  }
}

// The back lobe's shift and width against a simulation of A_1's paths: n >= 1 with P(n) ~ a_f^2n, then
// 2n forward events and one back event, each drawing its lobe by the energy the lobe sends into that half
// of the azimuths and adding its shift plus a normal deviate of its variance; per channel, then weighted
// by A_b over RGB as the tables are.
TEST(MultipleScattering, BackLobeSpreadMatchesASimulationOfThePaths) {
  HairMaterial blonde;
  blonde.absorption = absorptionFromColor(glm::dvec3(0.8, 0.65, 0.45));
  const MultipleScatteringTables t = multipleScatteringTables(blonde, kEntries);
  const int k = kEntries / 2;
  const auto fwd = physicalLobeFurnaceOver(sineOf(k), blonde, 0.5 * shading::kPi, shading::kPi, 16);
  const auto back = physicalLobeFurnaceOver(sineOf(k), blonde, 0.0, 0.5 * shading::kPi, 16);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  double weight = 0.0, mean = 0.0, second = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto pick = [&](const std::array<glm::dvec3, 3>& energy) {
      std::discrete_distribution<int> lobe({energy[0][c], energy[1][c], energy[2][c]});
      const int p = lobe(rng);
      return shading::physicalShift(p, blonde) + std::sqrt(shading::physicalVariance(p, blonde)) * normal(rng);
    };
    const double q = std::pow(t.forwardAlbedo[k][c], 2);
    std::geometric_distribution<int> extra(1.0 - q);  // n - 1 >= 0 with P ~ q^(n - 1)
    double sum = 0.0, sum2 = 0.0;
    const int paths = 200000;
    for (int i = 0; i < paths; ++i) {
      const int n = 1 + extra(rng);
      double x = pick(back);
      for (int e = 0; e < 2 * n; ++e) x += pick(fwd);
      sum += x, sum2 += x * x;
    }
    const double A = t.backScatter[k][c];
    weight += A, mean += A * sum / paths, second += A * (sum2 / paths - (sum / paths) * (sum / paths));
  }
  std::printf("shift %.2f deg (simulated %.2f), width %.2f deg (simulated %.2f)\n", glm::degrees(t.backShift[k]),
              glm::degrees(mean / weight), glm::degrees(t.backWidth[k]), glm::degrees(std::sqrt(second / weight)));
  EXPECT_NEAR(t.backShift[k], mean / weight, 0.01 * std::abs(mean / weight) + glm::radians(0.2));
  EXPECT_NEAR(t.backWidth[k], std::sqrt(second / weight), 0.02 * std::sqrt(second / weight));
}

// The device form of the back lobe (the physical M texture's fourth channel, sampled the way the shader
// samples it) integrates to 1 against cos theta_r d theta_r for every theta_i, so the back-scattered
// energy is A_b; and a material whose lobes are far narrower than the texels still gets finite values.
TEST(MultipleScattering, BackLobeTextureIntegratesToOneAgainstCosThetaR) {
  HairMaterial brown, blonde, narrow;
  blonde.absorption = absorptionFromColor(glm::dvec3(0.8, 0.65, 0.45));
  narrow.alphaR = 0.0;
  narrow.betaR = glm::radians(0.01);
  for (const HairMaterial* m : {&brown, &blonde}) {
    const MarschnerLut lut = buildPhysicalLut(*m, LutFormat::RGBA16F);
    // The layer a strand of roughness scale 1 reads (every layer holds the same back lobe).
    const float variation = float(m->roughnessVariation);
    const float invLayers = 1.0f / float(gpu::marschnerPhysicalMLayers(variation));
    const float layer = gpu::marschnerPhysicalMLayer(1.0f, variation);
    for (double degrees : {-85.0, -60.0, -20.0, 0.0, 35.0, 70.0, 88.0}) {
      const float si = float(std::sin(glm::radians(degrees)));
      double integral = 0.0;
      shading::gaussLegendre(-0.5 * shading::kPi, 0.5 * shading::kPi, 64, [&](double tr, double w) {
        const glm::vec4 c = gpu::marschnerPhysicalCoords(glm::vec4(si, float(std::sin(tr)), 0.0f, 0.0f));
        const float v = gpu::marschnerPhysicalMLayerV(c.y, layer, invLayers);
        integral += w * std::cos(tr) * sampleBilinear(lut.textures[0], c.x, v).w;
      });
      EXPECT_NEAR(integral, 1.0, 0.03) << "theta_i " << degrees;
    }
  }
  const MarschnerLut lut = buildPhysicalLut(narrow, LutFormat::RGBA16F);
  const MultipleScatteringTables t = multipleScatteringTables(narrow, kEntries);
  const std::vector<float>& m = lut.textures[0].data;
  for (std::size_t i = 0; i < m.size(); ++i) ASSERT_TRUE(std::isfinite(m[i])) << "channel " << i % 4 << " texel " << i / 4 << " " << m[i];
  for (const glm::dvec3& A : t.backScatter)
    for (int c = 0; c < 3; ++c) EXPECT_TRUE(A[c] >= 0.0 && A[c] <= 1.0) << A[c];
}

TEST(MultipleScattering, RefusesABadTableSize) {
  EXPECT_THROW(multipleScatteringTables(HairMaterial{}, 1), Error);
  EXPECT_THROW(multipleScatteringTables(HairMaterial{}, 5000), Error);
}

// The sky a visible fibre receives with dual scattering: single scattering's (1 - ln 2) / 2 where nothing
// goes on forward, half the sky where everything does, and in between for real hair, more for lighter hair
// and for red than blue (blonde passes more on). The closed form against a direct quadrature of
// (1/2) int_0^inf e^-x E_2(k x) dx for brown's k (k = 1 - the red mean forward albedo).
TEST(MultipleScattering, SkyVisibilityGrowsFromSingleScatteringsWithTheForwardAlbedo) {
  MultipleScatteringTables none, all;
  none.forwardAlbedo.assign(kEntries, glm::dvec3(0.0));
  all.forwardAlbedo.assign(kEntries, glm::dvec3(1.0));
  EXPECT_NEAR(skyVisibility(none).x, 0.5 * (1.0 - std::log(2.0)), 1e-12);
  EXPECT_NEAR(skyVisibility(all).y, 0.5, 1e-6);
  HairMaterial brown, blonde;
  blonde.absorption = absorptionFromColor({0.8, 0.65, 0.45});
  const glm::dvec3 vBrown = skyVisibility(multipleScatteringTables(brown, 32));
  const glm::dvec3 vBlonde = skyVisibility(multipleScatteringTables(blonde, 32));
  std::printf("sky visibility: brown %.4f %.4f %.4f, blonde %.4f %.4f %.4f\n", vBrown.x, vBrown.y, vBrown.z, vBlonde.x,
              vBlonde.y, vBlonde.z);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(vBrown[c], 0.5 * (1.0 - std::log(2.0)));
    EXPECT_GT(vBlonde[c], vBrown[c]);
    EXPECT_LT(vBlonde[c], 0.5);
  }
  EXPECT_GT(vBlonde.x, vBlonde.z);
  // (1/2) int e^-x E_2(k x) dx, E_2(z) = int_1^inf e^-zt / t^2 dt, for brown's red k, by quadrature.
  const double k = 1.0 - meanForwardAlbedo(multipleScatteringTables(brown, 32)).x;
  double integral = 0.0;
  shading::gaussLegendre(0.0, 1.0, 200, [&](double u, double wu) {  // t = 1 / u: dt / t^2 = du
    shading::gaussLegendre(0.0, 60.0, 200, [&](double x, double wx) { integral += wu * wx * std::exp(-x - k * x / u); });
  });
  EXPECT_NEAR(vBrown.x, 0.5 * integral, 1e-5);  // the quadrature's own error: 1.5e-6
}
