// Accuracy of the DEVICE kernel (shaders/brdf_eval.comp through BrdfEvaluator) against the exact
// double-precision S (hp::marschnerS) over 100,000 uniformly random (L, V, T), fixed seed. The measured
// figures are recorded in docs/SHADING.md ("Measured on the device").
#include <gtest/gtest.h>

#include <iostream>

#include "samples/tools/brdf_evaluator.h"
#include "compute/raster/marschner_textures.h"
#include "engine/core/shading/fibre_model.h"
#include "shaders/shared/strands.h"
#include "tests/render/brdf_test_util.h"
#include "tests/support/vk_fixture.h"

using hp::LutMode;
using hp::test::VulkanTest;

namespace {
constexpr std::size_t kSamples = 100'000;
constexpr unsigned kSeed = 20240611;

struct Reference {
  std::vector<hp::render::BrdfQuery> queries;
  std::vector<glm::dvec3> exact;
};

// The exact S of the float-rounded queries (what the device sees), computed once per process and model.
// The physical model's exact S integrates over h per sample, so it uses the first 20,000 queries.
const Reference& reference(hp::FibreModel model) {
  static const Reference marschner = [] {
    Reference r;
    r.queries = hp::test::randomQueries(kSamples, kSeed);
    const hp::HairMaterial m;
    for (const auto& q : r.queries) r.exact.push_back(hp::marschnerS(glm::dvec3(q.L), glm::dvec3(q.V), glm::dvec3(q.T), m));
    return r;
  }();
  static const Reference physical = [] {
    Reference r;
    r.queries = hp::test::randomQueries(20'000, kSeed);
    const hp::HairMaterial m;
    for (const auto& q : r.queries) r.exact.push_back(hp::physicalS(glm::dvec3(q.L), glm::dvec3(q.V), glm::dvec3(q.T), m));
    return r;
  }();
  return model == hp::FibreModel::Physical ? physical : marschner;
}

hp::test::DeviceAccuracy measure(const hp::vk::Context& ctx, LutMode mode) {
  const Reference& ref = reference(hp::fibreModelOf(mode));
  hp::render::MarschnerTextures textures(ctx, hp::HairMaterial{}, mode);
  std::vector<glm::vec3> s = hp::render::evaluateBrdfOnDevice(ctx, textures, ref.queries);
  hp::test::DeviceAccuracy a = hp::test::compareWithExact(s, ref.exact);
  const auto& w = ref.queries[a.worst];
  std::cout << "[device " << ctx.properties().deviceName << "] " << hp::lutModeName(mode) << ": " << a.str()
            << "\n  worst sample " << a.worst << ": L=(" << w.L.x << "," << w.L.y << "," << w.L.z << ") V=(" << w.V.x
            << "," << w.V.y << "," << w.V.z << ") T=(" << w.T.x << "," << w.T.y << "," << w.T.z << ")\n";
  return a;
}
}  // namespace

TEST_F(VulkanTest, BrdfDirectModeOnDeviceMatchesExactS) {
  auto a = measure(*ctx, LutMode::Direct);
  EXPECT_LE(a.p99, 0.001) << a.str();
  EXPECT_LE(a.relativeSum, 0.001) << a.str();
  // Guards the two numerical fixes (own asin/acos: max was 18.6%; phi from the vectors instead of
  // acos(cos phi): max was 0.47%, at phi ~ pi). Measured on lavapipe: 0.022%.
  EXPECT_LE(a.max, 0.002) << a.str();
}

TEST_F(VulkanTest, BrdfFloatModeOnDeviceMatchesExactS) {
  auto a = measure(*ctx, LutMode::Float);
  EXPECT_LE(a.median, 0.003) << a.str();
  EXPECT_LE(a.p99, 0.02) << a.str();
  EXPECT_LE(a.relativeSum, 0.02) << a.str();
}

TEST_F(VulkanTest, BrdfPhysicalModeOnDeviceMatchesExactS) {
  auto a = measure(*ctx, LutMode::Physical);
  EXPECT_LE(a.median, 0.003) << a.str();
  EXPECT_LE(a.p99, 0.02) << a.str();
  EXPECT_LE(a.relativeSum, 0.02) << a.str();
}

// The paper's 8-bit layout is an approximation by design (docs/SHADING.md): held to the figures recorded
// for it on the device ("Measured on the device": median 0.58%, p99 41%, sum 8.7%; CPU emulation 0.42% /
// 41% / 8.3%). p99 and sum come from the layout, not the device, so they get ~1.5x; the median depends on
// how the device filters 8-bit texels (lavapipe rounds the filtered value to 8 bits), so it keeps ~3x.
TEST_F(VulkanTest, BrdfPaperModeOnDeviceStaysWithinItsDocumentedAccuracy) {
  auto a = measure(*ctx, LutMode::Paper);
  EXPECT_LE(a.median, 0.02) << a.str();
  EXPECT_LE(a.p99, 0.6) << a.str();
  EXPECT_LE(a.relativeSum, 0.13) << a.str();
}

// Direct mode over the other caustic branches and absorptions (fewer samples each): same p99 bound.
TEST_F(VulkanTest, BrdfDirectModeOnDeviceMatchesExactSForOtherMaterials) {
  std::vector<hp::HairMaterial> materials(4);
  materials[0].absorption = {0.06, 0.1, 0.2};  // blonde
  materials[1].eta = 1.3;                      // caustic over a wider theta_d
  materials[2].eta = 2.2;                      // fade branch only
  materials[3].betaR = glm::radians(3.0);      // narrow lobes: M_TT is a 1.5-degree Gaussian
  materials[3].alphaR = glm::radians(-3.0);
  materials[3].wc = glm::radians(8.0);
  const auto queries = hp::test::randomQueries(30'000, kSeed + 1);
  hp::render::BrdfEvaluator evaluator(*ctx);
  for (const hp::HairMaterial& m : materials) {
    hp::render::MarschnerTextures textures(*ctx, m, LutMode::Direct);
    std::vector<glm::dvec3> exact;
    for (const auto& q : queries) exact.push_back(hp::marschnerS(glm::dvec3(q.L), glm::dvec3(q.V), glm::dvec3(q.T), m));
    auto a = hp::test::compareWithExact(evaluator.evaluate(textures, queries), exact);
    std::cout << "direct, eta " << m.eta << ", sigma_a.b " << m.absorption.b << ", beta_R "
              << glm::degrees(m.betaR) << " deg: " << a.str() << "\n";
    EXPECT_LE(a.p99, 0.001) << a.str();
    EXPECT_LE(a.relativeSum, 0.001) << a.str();
  }
}

// Each row's cuticle tilt offset and roughness scale (BrdfQuery::tilt, roughness: a strand's strandTilt and
// strandRoughness in the frame, the default material's variation of the latter) against the exact S of the
// material with alpha_R plus that offset and beta_R times that scale, row by row (the reference's per-strand
// material): the physical and direct modes within their plain bounds; the same rows without either miss by far
// more.
TEST_F(VulkanTest, BrdfPhysicalAndDirectModesOnDeviceTakeEachRowsTiltAndRoughness) {
  std::vector<hp::render::BrdfQuery> queries = hp::test::randomQueries(4'000, kSeed + 1);
  std::vector<hp::render::BrdfQuery> untilted = queries;
  const double variation = hp::HairMaterial{}.roughnessVariation;
  ASSERT_GT(variation, 0.0);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    queries[i].tilt = float(glm::radians(-5.0 + 10.0 * double(i % 101) / 100.0));
    queries[i].roughness = hp::gpu::strandRoughnessOfLevel(std::uint32_t(i % hp::gpu::STRAND_ROUGHNESS_LEVELS),
                                                           float(variation));
  }
  for (LutMode mode : {LutMode::Physical, LutMode::Direct}) {
    std::vector<glm::dvec3> exact;
    for (const auto& q : queries) {
      hp::HairMaterial m;
      m.alphaR += double(q.tilt);
      m.betaR *= double(q.roughness);
      exact.push_back(hp::exactS(hp::fibreModelOf(mode), glm::dvec3(q.L), glm::dvec3(q.V), glm::dvec3(q.T), m));
    }
    hp::render::MarschnerTextures textures(*ctx, hp::HairMaterial{}, mode);
    const auto a = hp::test::compareWithExact(hp::render::evaluateBrdfOnDevice(*ctx, textures, queries), exact);
    const auto without = hp::test::compareWithExact(hp::render::evaluateBrdfOnDevice(*ctx, textures, untilted), exact);
    std::cout << hp::lutModeName(mode) << " with each row's tilt and roughness: " << a.str() << "\n  without: " << without.str()
              << "\n";
    EXPECT_LE(a.median, 0.003) << a.str();
    EXPECT_LE(a.p99, 0.02) << a.str();
    EXPECT_LE(a.relativeSum, 0.02) << a.str();
    EXPECT_GT(without.relativeSum, 5.0 * a.relativeSum) << without.str();
  }
}
