// The exact S: closed forms, symmetry, sanity over random directions, lobe shapes, caustic branches.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "engine/core/shading/fresnel.h"
#include "engine/core/shading/marschner.h"
#include "engine/core/shading/marschner_terms.h"
#include "engine/core/shading/math_constants.h"
#include "tests/shading/random_directions.h"

using namespace hp;
using namespace hp::shading;
using hp::shading::kPi;  // one pi for every shading file (unity builds)

TEST(Marschner, NRIsTheClosedForm) {
  HairMaterial m;
  for (double td : {0.0, 0.4, -0.9})
    for (double phi = 0.0; phi <= kPi; phi += 0.1) {
      double e1 = bravaisEtaPrime(m.eta, td), e2 = bravaisEtaDoublePrime(m.eta, td);
      double expected = fresnel(e1, e2, -phi / 2) * std::cos(phi / 2) / 4;
      EXPECT_NEAR(lobeNR(phi, td, m), expected, 1e-15) << td << " " << phi;
    }
}

TEST(Marschner, BravaisIndicesAtNormalIncidenceAreEta) {
  EXPECT_DOUBLE_EQ(bravaisEtaPrime(1.55, 0.0), 1.55);
  EXPECT_DOUBLE_EQ(bravaisEtaDoublePrime(1.55, 0.0), 1.55);
  double td = 0.7, s = std::sin(td), c = std::cos(td);
  EXPECT_NEAR(bravaisEtaPrime(1.55, td), std::sqrt(1.55 * 1.55 - s * s) / c, 1e-15);
  EXPECT_NEAR(bravaisEtaDoublePrime(1.55, td), 1.55 * 1.55 * c / std::sqrt(1.55 * 1.55 - s * s), 1e-15);
}

TEST(Marschner, MIsTheShiftedGaussian) {
  HairMaterial m;
  EXPECT_NEAR(lobeM(0, m.alphaR, m), 1.0 / (m.betaR * std::sqrt(2 * kPi)), 1e-12);
  EXPECT_NEAR(lobeM(1, -m.alphaR / 2, m), 1.0 / (m.betaR / 2 * std::sqrt(2 * kPi)), 1e-12);
  EXPECT_NEAR(lobeM(2, -1.5 * m.alphaR, m), 1.0 / (2 * m.betaR * std::sqrt(2 * kPi)), 1e-12);
}

TEST(Marschner, SIsSymmetricInLAndV) {
  HairMaterial m;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 2000; ++i) {
    auto t = test::uniformTriple(rng);
    glm::dvec3 a = marschnerS(t.L, t.V, t.T, m), b = marschnerS(t.V, t.L, t.T, m);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-12 * (std::abs(a[c]) + 1e-300));
  }
}

TEST(Marschner, FlippingTheTangentIsSymmetricOnlyWithoutShift) {
  // T -> -T maps theta_h -> -theta_h; M_p(theta_h - alpha_p) is even only if alpha_R = 0.
  HairMaterial m;
  m.alphaR = 0.0;
  std::mt19937_64 rng(8);
  for (int i = 0; i < 500; ++i) {
    auto t = test::uniformTriple(rng);
    glm::dvec3 a = marschnerS(t.L, t.V, t.T, m), b = marschnerS(t.L, t.V, -t.T, m);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-10 * (std::abs(a[c]) + 1e-300));
  }
  HairMaterial shifted;
  glm::dvec3 L(1, 0, -0.13), V(0.2, 1, -0.13), T(0, 0, 1);  // theta_h ~ alpha_R
  EXPECT_GT(std::abs(marschnerS(L, V, T, shifted).x - marschnerS(L, V, -T, shifted).x), 1e-3);
}

TEST(Marschner, RotationAboutTheTangentChangesNothing) {
  HairMaterial m;
  glm::dvec3 T(0, 0, 1), L(0.3, 0.4, 0.5), V(-0.7, 0.2, -0.1);
  double c = std::cos(1.1), s = std::sin(1.1);
  auto rot = [&](glm::dvec3 x) { return glm::dvec3(c * x.x - s * x.y, s * x.x + c * x.y, x.z); };
  glm::dvec3 a = marschnerS(L, V, T, m), b = marschnerS(rot(L), rot(V), T, m);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * a[k]);
}

TEST(Marschner, FiniteAndNonNegativeOverRandomDirections) {
  HairMaterial m;
  std::mt19937_64 rng(1);
  for (int i = 0; i < 100000; ++i) {
    auto t = test::uniformTriple(rng);
    glm::dvec3 s = marschnerS(t.L, t.V, t.T, m);
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(s[c])) << i;
      ASSERT_GE(s[c], 0.0) << i;
    }
  }
}

TEST(Marschner, DegenerateDirectionsAreFinite) {
  HairMaterial m;
  glm::dvec3 T(0, 0, 1);
  glm::dvec3 cases[][2] = {{T, {1, 0, 0}}, {{1, 0, 0}, -T}, {T, T}, {-T, T}, {T, -T}, {{0, 1, 0}, {0, 1, 0}}};
  for (auto& c : cases) {
    glm::dvec3 s = marschnerS(c[0], c[1], T, m);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(std::isfinite(s[k]));
      EXPECT_GE(s[k], 0.0);
    }
  }
  EXPECT_EQ(shadingAngles(T, {1, 0, 0}, T).cosPhi, 0.0);  // no azimuth: phi = pi/2
}

TEST(Marschner, TTPeaksNearBackScatterAzimuthPi) {
  HairMaterial m;
  for (double td : {0.0, 0.3, 0.6}) {
    double bestPhi = 0, best = -1;
    for (double phi = 0.0; phi <= kPi + 1e-9; phi += kPi / 720) {
      double v = lobeNTT(phi, td, m).x;
      if (v > best) best = v, bestPhi = phi;
    }
    EXPECT_NEAR(bestPhi, kPi, 0.02) << td;
    EXPECT_NEAR(lobeNTT(kPi / 4, td, m).x, 0.0, 1e-12);  // TT cannot exit far from the forward direction
  }
}

TEST(Marschner, TRTCausticBranches) {
  HairMaterial m;
  // eta' = sqrt(eta^2 - s^2)/cos: eta' < 2 near theta_d = 0, >= 2 for large theta_d.
  TrtCaustic low = trtCaustic(0.0, m);
  EXPECT_TRUE(low.causticBranch);
  EXPECT_EQ(low.t, 1.0);
  EXPECT_GT(low.hc, 0.5);
  EXPECT_LE(low.dh, m.dhM);
  double td = 1.0;  // eta' ~ 2.63 > 2 + dEta: fully faded
  ASSERT_GE(bravaisEtaPrime(m.eta, td), 2.0 + m.dEta);
  TrtCaustic faded = trtCaustic(td, m);
  EXPECT_FALSE(faded.causticBranch);
  EXPECT_EQ(faded.t, 0.0);
  EXPECT_EQ(faded.dh, m.dhM);
  // Inside the fade range 2 <= eta' < 2 + dEta: 0 < t < 1, and N_TRT is the raw sum damped by t.
  double tdMid = std::asin(std::sqrt((2.15 * 2.15 - m.eta * m.eta) / (2.15 * 2.15 - 1)));
  ASSERT_NEAR(bravaisEtaPrime(m.eta, tdMid), 2.15, 1e-9);
  TrtCaustic mid = trtCaustic(tdMid, m);
  EXPECT_GT(mid.t, 0.0);
  EXPECT_LT(mid.t, 1.0);
  // With t = 0 the caustic changes nothing.
  EXPECT_EQ(lobeNTRT(0.7, td, m), lobeNRaw(2, 0.7, td, m));
  // In the caustic branch the glint adds energy at phi_c.
  double phic = std::remainder(low.phic, 2 * kPi);
  EXPECT_GT(lobeNTRT(std::abs(phic), 0.0, m).x, 0.0);
}

TEST(Marschner, NIsContinuousAcrossTheCausticBranchSwitch) {
  HairMaterial m;
  double tdSwitch = std::asin(std::sqrt((4 - m.eta * m.eta) / 3));  // eta' = 2
  for (double phi : {0.1, 0.5, 1.0, 2.0}) {
    glm::dvec3 a = lobeNTRT(phi, tdSwitch - 1e-7, m), b = lobeNTRT(phi, tdSwitch + 1e-7, m);
    EXPECT_NEAR(a.x, b.x, 1e-4 * (a.x + 1e-6)) << phi;
  }
}

// S through the public entry point (vectors -> shadingAngles -> marschnerLobes -> total) against the
// three lobes assembled here from their factors, at theta_h, theta_d and phi taken from the angles that
// built the vectors (not from asin/acos of the sines marschnerS works with); and the separated lobes
// against the same factors.
TEST(Marschner, LobeDecompositionSumsToS) {
  HairMaterial m;
  const glm::dvec3 T(0, 0, 1);
  const double configs[][3] = {{0.3, -0.2, 2.5}, {-0.7, 0.4, 0.3}, {0.05, 0.1, 1.2}, {-0.9, -1.2, 2.9}, {0.6, 0.5, 1.9}};
  for (const auto& c : configs) {
    const double ti = c[0], tr = c[1], phi = c[2];
    const glm::dvec3 L(std::cos(ti), 0, std::sin(ti));
    const glm::dvec3 V(std::cos(tr) * std::cos(phi), std::cos(tr) * std::sin(phi), std::sin(tr));
    const double th = 0.5 * (ti + tr), td = 0.5 * (tr - ti);
    const glm::dvec3 r(lobeM(0, th, m) * lobeNR(phi, td, m));
    const glm::dvec3 tt = lobeM(1, th, m) * lobeNTT(phi, td, m);
    const glm::dvec3 trt = lobeM(2, th, m) * lobeNTRT(phi, td, m);
    const glm::dvec3 expected = (r + tt + trt) / (std::cos(td) * std::cos(td));
    const glm::dvec3 s = marschnerS(L, V, T, m);
    for (int k = 0; k < 3; ++k) {
      ASSERT_GT(expected[k], 0.0) << ti << " " << tr << " " << phi;
      EXPECT_NEAR(s[k], expected[k], 1e-9 * expected[k]) << ti << " " << tr << " " << phi << " channel " << k;
    }
    const MarschnerLobes l = marschnerLobes(std::sin(ti), std::sin(tr), std::cos(phi), m);
    EXPECT_NEAR(l.mR, lobeM(0, th, m), 1e-9 * l.mR);
    EXPECT_NEAR(l.mTT, lobeM(1, th, m), 1e-9 * l.mTT);
    EXPECT_NEAR(l.mTRT, lobeM(2, th, m), 1e-9 * l.mTRT);
    EXPECT_NEAR(l.nR, lobeNR(phi, td, m), 1e-9 * l.nR);
    EXPECT_NEAR(l.nTT.y, lobeNTT(phi, td, m).y, 1e-9 * l.nTT.y + 1e-300);
    EXPECT_NEAR(l.nTRT.y, lobeNTRT(phi, td, m).y, 1e-9 * l.nTRT.y);
    EXPECT_NEAR(l.cosThetaD, std::cos(td), 1e-12);
  }
}

// With an absorption that zeroes every transmitted path (exp(-2e4 ...) underflows to 0), TT and TRT
// (caustic included) vanish and S is the R lobe in closed form:
//   S = g(beta_R, theta_h - alpha_R) F(eta', eta'', phi/2) cos(phi/2) / 4 / cos^2 theta_d.
TEST(Marschner, OpaqueFibreSIsTheClosedFormRLobe) {
  HairMaterial m;
  m.absorption = glm::dvec3(1e4);
  const glm::dvec3 T(0, 0, 1);
  for (double ti : {-0.4, 0.1, 0.5})
    for (double tr : {-0.3, 0.0, 0.7})
      for (double phi : {0.2, 1.0, 2.2, 3.0}) {
        const glm::dvec3 L(std::cos(ti), 0, std::sin(ti));
        const glm::dvec3 V(std::cos(tr) * std::cos(phi), std::cos(tr) * std::sin(phi), std::sin(tr));
        const double th = 0.5 * (ti + tr), td = 0.5 * (tr - ti);
        const double x = th - m.alphaR;
        const double g = std::exp(-x * x / (2 * m.betaR * m.betaR)) / (m.betaR * std::sqrt(2 * kPi));
        const double f = fresnel(bravaisEtaPrime(m.eta, td), bravaisEtaDoublePrime(m.eta, td), phi / 2);
        const double expected = g * f * std::cos(phi / 2) / 4 / (std::cos(td) * std::cos(td));
        const glm::dvec3 s = marschnerS(L, V, T, m);
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(s[k], expected, 1e-9 * expected) << ti << " " << tr << " " << phi << " channel " << k;
      }
}

// tests/CMakeLists.txt leaves tests/shading/glsl_port_test.cpp (GlslPort.DirectModeLogicMatchesTheExactS)
// out of clang < 16 builds (the sanitizer build): it needs parenthesized aggregate initialization
// (P0960). This stands in for it there, so the run reports the missing check and why instead of
// silently having one test fewer.
#if defined(__clang__) && !defined(__apple_build_version__) && __clang_major__ < 16
TEST(GlslPort, DirectModeLogicMatchesTheExactSIsLeftOutOfThisBuild) {
  GTEST_SKIP() << "tests/shading/glsl_port_test.cpp needs parenthesized aggregate initialization (P0960, "
                  "clang >= 16; this is clang "
               << __clang_major__ << "), so tests/CMakeLists.txt leaves it out; the gcc build (make test) runs it";
}
#endif
