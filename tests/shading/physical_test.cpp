// The physical fibre model (docs/THEORY.md §4): normalisation of M, energy of the A_p, the white furnace
// over a grid of outgoing directions, convergence of the azimuthal quadrature, basic symmetries.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "engine/core/shading/furnace.h"
#include "engine/core/shading/marschner.h"
#include "engine/core/shading/physical.h"
#include "engine/core/shading/quadrature.h"
#include "engine/core/shading/math_constants.h"
#include "tests/shading/random_directions.h"

using namespace hp;

namespace {
using hp::shading::kPi;  // one pi for every shading file (unity builds)

HairMaterial white() {
  HairMaterial m;
  m.absorption = glm::dvec3(0.0);
  return m;
}

// Outgoing directions: theta_r from -85 to 85 deg.
std::vector<double> outgoingSines() {
  std::vector<double> s;
  for (int d = -85; d <= 85; d += 17) s.push_back(std::sin(d * kPi / 180.0));
  return s;
}
}  // namespace

TEST(PhysicalModel, LongitudinalLobesIntegrateToOne) {
  HairMaterial m;
  for (double betaDeg : {2.0, 7.5, 20.0}) {
    m.betaR = betaDeg * kPi / 180.0;
    for (double sr : outgoingSines())
      for (int p = 0; p < 3; ++p) {
        double sum = 0;
        shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, 256, [&](double t, double w) {
          sum += w * std::cos(t) * shading::physicalM(p, std::sin(t), sr, m);
        });
        EXPECT_NEAR(sum, 1.0, 1e-6) << "p " << p << " beta " << betaDeg << " sin theta_r " << sr;
      }
  }
}

TEST(PhysicalModel, AttenuationsSumToOneWithoutAbsorption) {
  HairMaterial m = white();
  for (double sr : outgoingSines()) {
    auto e = shading::physicalLobeEnergy(sr, m);
    glm::dvec3 sum = e[0] + e[1] + e[2] + e[3];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 1e-9);
  }
}

TEST(PhysicalModel, WhiteFurnaceIsOneWithoutAbsorption) {
  for (double sr : outgoingSines()) {
    glm::dvec3 w = whiteFurnace(FibreModel::Physical, sr, white());
    std::cout.precision(9);
    std::cout << "sin theta_r " << sr << ": " << w.r << " " << w.g << " " << w.b << "\n";
    for (int c = 0; c < 3; ++c) {
      EXPECT_GE(w[c], 0.97);
      EXPECT_LE(w[c], 1.0 + 1e-6);
    }
  }
}

TEST(PhysicalModel, WhiteFurnaceIsBelowOneWithAbsorption) {
  HairMaterial blonde;
  blonde.absorption = {0.06, 0.1, 0.2};
  HairMaterial dark;
  dark.absorption = {3.0, 3.5, 4.0};
  dark.betaR = 12.0 * kPi / 180.0;
  for (const HairMaterial& m : {HairMaterial{}, blonde, dark})
    for (double sr : outgoingSines()) {
      glm::dvec3 w = whiteFurnace(FibreModel::Physical, sr, m);
      for (int c = 0; c < 3; ++c) {
        EXPECT_LE(w[c], 1.0);
        EXPECT_GT(w[c], 0.0);
      }
    }
}

TEST(PhysicalModel, PaperModelIsMeasuredAboveOne) {
  // The 2003 model's known flaw (docs/THEORY.md §4): the furnace integral is near 2. Coarse grid: the caustics
  // are integrable singularities, so this is a measurement, not a bound.
  glm::dvec3 w = whiteFurnace(FibreModel::Marschner, 0.0, white(), 48);
  std::cout << "paper model, theta_r = 0: " << w.r << " " << w.g << " " << w.b << "\n";
  EXPECT_GT(w.g, 1.5);
}

TEST(PhysicalModel, SIsFiniteNonNegativeAndRotationInvariant) {
  HairMaterial m;
  glm::dvec3 T = glm::normalize(glm::dvec3(0.2, 1.0, -0.3));
  glm::dvec3 L = glm::normalize(glm::dvec3(1.0, 0.3, 0.2)), V = glm::normalize(glm::dvec3(-0.4, -0.2, 1.0));
  glm::dvec3 s = physicalS(L, V, T, m);
  // Rotate L and V about T by 40 degrees: same angles, same S.
  auto rot = [&](glm::dvec3 x) {
    double a = 40.0 * kPi / 180.0;
    return x * std::cos(a) + glm::cross(T, x) * std::sin(a) + T * glm::dot(T, x) * (1 - std::cos(a));
  };
  glm::dvec3 r = physicalS(rot(L), rot(V), T, m);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GE(s[c], 0.0);
    EXPECT_NEAR(s[c], r[c], 1e-9 * (1 + s[c]));
  }
  glm::dvec3 pole = physicalS(T, V, T, m);
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(pole[c]));
}

TEST(PhysicalModel, RLobePeaksAtTheTiltedSpecularAngle) {
  HairMaterial m;
  m.absorption = glm::dvec3(50.0);  // R only
  // theta_r = 20 deg: R peaks at theta_i + theta_r = 2 alpha_R (theta_h = alpha_R, as in the paper).
  double tr = 20.0 * kPi / 180.0, best = -1, bestTi = 0;
  for (double ti = -kPi / 2; ti < kPi / 2; ti += 0.001) {
    double v = shading::physicalM(0, std::sin(ti), std::sin(tr), m);
    if (v > best) best = v, bestTi = ti;
  }
  EXPECT_NEAR(bestTi + tr, 2.0 * m.alphaR, 0.03);  // d'Eon's lobe is not exactly centred
}

// The ambient term's albedo (hp::skyAlbedo, the furnace averaged over outgoing directions): 1 for a
// white physical fibre, between the furnace's extremes for brown. For the paper's model it is checked
// against an estimate that shares none of the quadrature: Monte Carlo over independent uniform (L, V, T)
// of the same integral, albedo = E_V[W(V)] = 4 pi E_{L,V}[S(L, V, T) cos theta_i] (a uniform V has
// density cos(theta_r)/2 in theta_r, the (1/2) cos(theta_r) weight of the definition; W is the integral of
// S cos theta_i over the sphere of L, 4 pi times its mean). Then the coarse rule against a finer one.
TEST(PhysicalModel, SkyAlbedoIsTheFurnaceAveragedOverOutgoingDirections) {
  const glm::dvec3 w = skyAlbedo(FibreModel::Physical, white());
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(w[c], 1.0, 1e-5);
  const HairMaterial brown;
  const glm::dvec3 a = skyAlbedo(FibreModel::Physical, brown);
  const glm::dvec3 at0 = whiteFurnace(FibreModel::Physical, 0.0, brown), at85 = whiteFurnace(FibreModel::Physical, 0.996, brown);
  for (int c = 0; c < 3; ++c) {
    EXPECT_GT(a[c], 0.9 * std::min(at0[c], at85[c]));
    EXPECT_LT(a[c], std::max(at0[c], at85[c]));
  }
  EXPECT_GT(a.r, 2.0 * a.b);  // brown stays red under a white sky
  std::cout << "sky albedo, physical brown: " << a.r << " " << a.g << " " << a.b << "\n";
  const glm::dvec3 m = skyAlbedo(FibreModel::Marschner, brown);
  std::cout << "sky albedo, Marschner brown: " << m.r << " " << m.g << " " << m.b << "\n";

  // Monte Carlo, fixed seed. 400,000 samples give a standard error of ~0.45% per channel (measured:
  // 0.0034 / 0.0021 / 0.0015 against 0.721 / 0.457 / 0.255). Allowed: 5 standard errors, estimated from
  // the samples themselves, plus 0.5% for the coarse quadrature (furnace.h: within 0.5% of 64 panels).
  constexpr int kMcSamples = 400'000;
  std::mt19937_64 rng(20240611);
  glm::dvec3 sum(0.0), sumSq(0.0);
  for (int i = 0; i < kMcSamples; ++i) {
    const test::Triple t = test::uniformTriple(rng);
    const double sinThetaI = glm::dot(t.L, t.T);
    const glm::dvec3 f = 4.0 * kPi * marschnerS(t.L, t.V, t.T, brown) * std::sqrt(std::max(0.0, 1.0 - sinThetaI * sinThetaI));
    sum += f;
    sumSq += f * f;
  }
  const glm::dvec3 mc = sum / double(kMcSamples);
  const glm::dvec3 stdErr = glm::sqrt((sumSq / double(kMcSamples) - mc * mc) / double(kMcSamples));
  std::cout << "sky albedo, Marschner brown, Monte Carlo: " << mc.r << " " << mc.g << " " << mc.b << " (std. err. "
            << stdErr.r << " " << stdErr.g << " " << stdErr.b << ")\n";
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(stdErr[c], 0.01 * mc[c]) << "channel " << c << ": the estimate is too noisy to check anything";
    EXPECT_NEAR(m[c], mc[c], 5.0 * stdErr[c] + 0.005 * mc[c]) << "channel " << c;
  }

  // Convergence of the coarse rule (4 panels) against 8 panels and 16 outgoing nodes.
  glm::dvec3 fine(0.0);
  shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, 2, [&](double t, double wt) {
    fine += 0.5 * wt * std::cos(t) * whiteFurnace(FibreModel::Marschner, std::sin(t), brown, 8);
  });
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], fine[c], 0.01 * fine[c]) << "channel " << c;
}
