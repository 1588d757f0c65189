// LUT accuracy against the exact S over 100,000 uniformly random (L, V, T) (fixed seed).
// `float` mode has hard limits; `paper` mode is held to the figures docs/SHADING.md records for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <utility>
#include <vector>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/lut_sampler.h"
#include "shaders/shared/marschner.h"
#include "shaders/shared/strands.h"
#include "tests/shading/accuracy.h"

using namespace hp;

namespace {
constexpr int kSamples = 100000;
constexpr unsigned kSeed = 20240611;

struct Named {
  const char* name;
  HairMaterial m;
};

test::AccuracyStats measure(const MarschnerLut& lut, int subTexelBits = 0) {
  LutSamplerOptions o;
  o.subTexelBits = subTexelBits;
  return test::measureAccuracy(
      [&](glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) { return evaluateLut(lut, L, V, T, o); },
      lut.material, kSamples, kSeed);
}
}  // namespace

TEST(LutAccuracy, FloatModeMeetsTheLimits) {
  HairMaterial m;
  MarschnerLut lut = buildLut(LutMode::Float, m);
  test::AccuracyStats s = measure(lut);
  std::cout << "[float RGBA16F] " << s.str() << "\n";
  EXPECT_LE(s.median, 0.003);
  EXPECT_LE(s.p99, 0.02);
  EXPECT_LE(s.relativeSum, 0.02);
}

// The variants docs/SHADING.md measures beside the shipped RGBA16F: the same limits as the shipped
// form (measured: RGBA32F median 0.0008%, p99 0.085%, sum 0.17%; 8-bit weights 0.0021% / 0.087% /
// 0.18%, as RGBA16F). Full-precision texels cannot make the median worse than half-precision ones: the
// layout and the filter are the same, only the texel rounding differs (0.0008% against 0.0021%).
TEST(LutAccuracy, FloatModeVariantsMeetTheLimits) {
  HairMaterial m;
  LutBuildOptions o;
  o.floatFormat = LutFormat::RGBA32F;
  const test::AccuracyStats shipped = measure(buildLut(LutMode::Float, m));
  const test::AccuracyStats full = measure(buildLut(LutMode::Float, m, o));
  const test::AccuracyStats weights8 = measure(buildLut(LutMode::Float, m), 8);
  std::cout << "[float RGBA32F] " << full.str() << "\n";
  std::cout << "[float RGBA16F, 8-bit weights] " << weights8.str() << "\n";
  for (const auto& [name, s] : {std::pair{"RGBA32F", full}, std::pair{"8-bit weights", weights8}}) {
    EXPECT_LE(s.median, 0.003) << name;
    EXPECT_LE(s.p99, 0.02) << name;
    EXPECT_LE(s.relativeSum, 0.02) << name;
  }
  EXPECT_LE(full.median, shipped.median) << "RGBA32F " << full.str() << ", RGBA16F " << shipped.str();
}

// The paper's form is an approximation by design: its bounds are the figures docs/SHADING.md records
// for it (CPU emulation: RGBA8 median 0.42%, p99 41%, sum 8.3%; the same layout in RGBA32F 0.067% /
// 41% / 8.0%) with a margin of about 1.5x (2x on the medians, which depend on rounding), so a
// regression of the layout or of the 8-bit packing fails. p99 and sum come from the layout (M_TT for
// M_TRT, cos phi indexing), the median from the 8 bits: quantisation must make the median worse.
TEST(LutAccuracy, PaperModeStaysWithinItsDocumentedAccuracy) {
  HairMaterial m;
  const test::AccuracyStats s = measure(buildLut(LutMode::Paper, m));
  std::cout << "[paper RGBA8 128x128] " << s.str() << "\n";
  EXPECT_LE(s.median, 0.008) << s.str();
  EXPECT_LE(s.p99, 0.6) << s.str();
  EXPECT_LE(s.relativeSum, 0.12) << s.str();
  LutBuildOptions o;
  o.paperFormat = LutFormat::RGBA32F;  // same layout without 8-bit quantisation: the layout's own error
  const test::AccuracyStats layout = measure(buildLut(LutMode::Paper, m, o));
  std::cout << "[paper layout, RGBA32F 128x128] " << layout.str() << "\n";
  EXPECT_LE(layout.median, 0.0015) << layout.str();
  EXPECT_LE(layout.p99, 0.6) << layout.str();
  EXPECT_LE(layout.relativeSum, 0.12) << layout.str();
  EXPECT_GT(s.median, layout.median) << "8 bits " << s.str() << ", RGBA32F " << layout.str();
}

TEST(LutAccuracy, FloatModeMeetsTheLimitsForOtherMaterials) {
  std::vector<Named> materials(5);
  materials[0].name = "blonde";
  materials[0].m.absorption = {0.06, 0.1, 0.2};
  materials[1].name = "eta 1.3, wide caustic";
  materials[1].m.eta = 1.3;
  materials[2].name = "eta 2.2, fade branch only";
  materials[2].m.eta = 2.2;
  materials[3].name = "narrow beta 3 deg, alpha -3 deg, wc 8 deg";
  materials[3].m.betaR = glm::radians(3.0);
  materials[3].m.alphaR = glm::radians(-3.0);
  materials[3].m.wc = glm::radians(8.0);
  materials[4].name = "black, wide beta 12 deg";
  materials[4].m.absorption = {3.0, 3.5, 4.0};
  materials[4].m.betaR = glm::radians(12.0);
  for (const Named& n : materials) {
    test::AccuracyStats s = measure(buildLut(LutMode::Float, n.m));
    std::cout << "[float RGBA16F, " << n.name << "] " << s.str() << "\n";
    EXPECT_LE(s.median, 0.003) << n.name;
    EXPECT_LE(s.p99, 0.02) << n.name;
    EXPECT_LE(s.relativeSum, 0.02) << n.name;
  }
}

// The physical model's LUT form against its exact double evaluation. Fewer samples than the Marschner
// modes: the exact physical S integrates over h per sample.
TEST(LutAccuracy, PhysicalModeMeetsTheLimits) {
  std::vector<Named> materials(4);
  materials[0].name = "default brown";
  materials[1].name = "blonde";
  materials[1].m.absorption = {0.06, 0.1, 0.2};
  materials[2].name = "narrow beta 3 deg, alpha -3 deg, betaN 4 deg";
  materials[2].m.betaR = glm::radians(3.0);
  materials[2].m.alphaR = glm::radians(-3.0);
  materials[2].m.betaN = glm::radians(4.0);
  materials[3].name = "black, wide beta 12 deg, eta 1.3";
  materials[3].m.absorption = {3.0, 3.5, 4.0};
  materials[3].m.betaR = glm::radians(12.0);
  materials[3].m.eta = 1.3;
  for (const Named& n : materials) {
    MarschnerLut lut = buildLut(LutMode::Physical, n.m);
    test::AccuracyStats s = test::measureAccuracy(
        [&](glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) { return evaluateLut(lut, L, V, T); }, n.m, 20000, kSeed,
        FibreModel::Physical);
    std::cout << "[physical RGBA16F, " << n.name << "] " << s.str() << "\n";
    EXPECT_LE(s.median, 0.003) << n.name;
    EXPECT_LE(s.p99, 0.02) << n.name;
    EXPECT_LE(s.relativeSum, 0.02) << n.name;
  }
}

// A strand's cuticle tilt offset (MarschnerParams.caustic.z, shaders/shared/strands.h strandTilt): the one
// physical texture, built at the material's alpha_R, read at each lobe's shifted theta_r, against the exact
// S of the material with alpha_R + tilt (the reference's per-strand material), within the untilted limits.
// Negative control: the same lookups without the tilt miss that exact S by far more.
TEST(LutAccuracy, PhysicalModeTakesAStrandsTiltLikeTheExactModel) {
  const HairMaterial m;
  const MarschnerLut lut = buildLut(LutMode::Physical, m);
  for (double tiltDeg : {-3.0, 5.0}) {
    const float tilt = float(glm::radians(tiltDeg));
    HairMaterial tilted = m;
    tilted.alphaR += double(tilt);
    const test::AccuracyStats s = test::measureAccuracy(
        [&](glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) { return evaluateLut(lut, L, V, T, {}, tilt); }, tilted, 10000,
        kSeed, FibreModel::Physical);
    const test::AccuracyStats untilted = test::measureAccuracy(
        [&](glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) { return evaluateLut(lut, L, V, T); }, tilted, 10000, kSeed,
        FibreModel::Physical);
    std::cout << "[physical, tilt " << tiltDeg << " deg] " << s.str() << "; without the tilt " << untilted.str()
              << "\n";
    EXPECT_LE(s.median, 0.003) << tiltDeg;
    EXPECT_LE(s.p99, 0.02) << tiltDeg;
    EXPECT_LE(s.relativeSum, 0.02) << tiltDeg;
    EXPECT_GT(untilted.relativeSum, 5.0 * s.relativeSum) << tiltDeg;
  }
}

// A strand's roughness scale (MarschnerParams.caustic.w, shaders/shared/strands.h strandRoughness, one of its
// levels): the physical texture's layer of that level, built at beta_R x the level's scale, against the exact S
// of the material with beta_R x scale (the reference's per-strand material), within the one-layer limits, at
// every level of the largest variation. Negative control: the same lookups at scale 1 miss that exact S by far
// more at the variation's ends.
TEST(LutAccuracy, PhysicalModeTakesAStrandsRoughnessLikeTheExactModel) {
  HairMaterial m;
  m.roughnessVariation = 0.25;
  const MarschnerLut lut = buildLut(LutMode::Physical, m);
  ASSERT_EQ(lut.textures.at(0).height, gpu::MARSCHNER_PHYSICAL_M_SIZE * gpu::MARSCHNER_PHYSICAL_M_LAYERS);
  for (std::uint32_t level = 0; level < gpu::STRAND_ROUGHNESS_LEVELS; ++level) {
    const float scale = gpu::strandRoughnessOfLevel(level, float(m.roughnessVariation));
    HairMaterial rough = m;
    rough.betaR *= double(scale);
    const auto lookup = [&](float s) {
      return [&lut, s](glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) { return evaluateLut(lut, L, V, T, {}, 0.0f, s); };
    };
    const test::AccuracyStats s = test::measureAccuracy(lookup(scale), rough, 4000, kSeed, FibreModel::Physical);
    std::cout << "[physical, roughness x" << scale << "] " << s.str() << "\n";
    EXPECT_LE(s.median, 0.003) << scale;
    EXPECT_LE(s.p99, 0.02) << scale;
    EXPECT_LE(s.relativeSum, 0.02) << scale;
    if (level == 0 || level + 1 == gpu::STRAND_ROUGHNESS_LEVELS) {
      const test::AccuracyStats unscaled = test::measureAccuracy(lookup(1.0f), rough, 4000, kSeed, FibreModel::Physical);
      std::cout << "  read at x1: " << unscaled.str() << "\n";
      EXPECT_GT(unscaled.relativeSum, 5.0 * s.relativeSum) << scale;
    }
  }
}

// Without a roughness variation the M texture is one layer; with one, a strand of scale 1 reads the middle layer,
// the same lobes (to the rounding of its v coordinate in the taller texture).
TEST(LutAccuracy, PhysicalModeWithoutRoughnessVariationBuildsOneLayer) {
  HairMaterial m;
  m.roughnessVariation = 0.0;
  const MarschnerLut lut = buildLut(LutMode::Physical, m);
  EXPECT_EQ(lut.textures.at(0).height, gpu::MARSCHNER_PHYSICAL_M_SIZE);
  const glm::dvec3 L(0.3, 0.5, 0.8), V(-0.4, 0.2, 0.9), T(0.0, 1.0, 0.1);
  HairMaterial varied = m;
  varied.roughnessVariation = 0.2;
  const MarschnerLut layered = buildLut(LutMode::Physical, varied);
  const glm::dvec3 one = evaluateLut(lut, L, V, T), middle = evaluateLut(layered, L, V, T);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(one[c], middle[c], 1e-4 * std::max(1.0, one[c])) << c;
}
