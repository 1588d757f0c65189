// The compute raster's shade variants (compute/raster/shade_variant.h): a fibre compiled into the shade pass
// must shade exactly as the run-time form that reads it from the parameter blocks. On the device: over the
// same tile lists (one binning, the shade and fine steps run twice), each fibre model, and the physical one
// with both scatterings, lit by the sun, the fixed fibre's image against the run-time one's, and a fibre not
// prepared shading with the run-time form; the models' images differ from each other, so the comparison
// would see a variant that shaded another fibre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "compute/raster/shade_variant.h"
#include "tests/render/raster_rig.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
constexpr VkExtent2D kVariantExtent{64, 48};
constexpr float kVariantFov = 0.8f;
// The fixed fibre's largest radiance difference from the run-time form's (lavapipe: 0, the same arithmetic);
// every two fibres' images differ by more than 10x this (the closest, paper and float lookups: 0.0039).
constexpr double kSame = 1e-4;

hp::gpu::RenderFrame frameWith(std::uint32_t lights, std::uint32_t scattering) {
  hp::gpu::RenderFrame frame{};
  frame.lightCount.x = lights;
  frame.options.z = scattering;
  return frame;
}

hp::gpu::MarschnerParams fibreParams(std::uint32_t mode) {
  hp::gpu::MarschnerParams params{};
  params.control.x = mode;
  return params;
}

// A fan of 2-pixel strands through the image's centre at 12 angles, at two depths: tangents all around.
std::vector<hp::test::PixelStrand> fan() {
  std::vector<hp::test::PixelStrand> strands;
  const glm::vec2 centre(31.3f, 23.6f);
  for (int i = 0; i < 12; ++i) {
    const float rad = glm::radians(15.0f * float(i) + 4.0f);
    const glm::vec2 dir(std::cos(rad), std::sin(rad));
    strands.push_back({centre - 40.0f * dir, centre + 40.0f * dir, i % 2 == 0 ? 1.0f : 1.4f, 2.0f, 1.0f});
  }
  return strands;
}

// The largest difference in radiance (relative to max(1, |a|)) and the total radiance of a.
struct Comparison {
  double largest = 0.0;
  double total = 0.0;
};

Comparison compare(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  Comparison c;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      c.largest = std::max(c.largest, std::abs(double(a[i][k]) - b[i][k]) / std::max(1.0, std::abs(double(a[i][k]))));
      c.total += a[i][k];
    }
  return c;
}
}  // namespace

TEST(ShadeVariant, TakesTheLightLoopAndTheFibreTheFrameAndParametersGive) {
  using namespace hp::gpu;
  const auto variant = [](std::uint32_t lights, std::uint32_t scattering, std::uint32_t mode) {
    return hp::compute::shadeVariantOf(frameWith(lights, scattering), fibreParams(mode));
  };
  EXPECT_EQ(variant(1, RENDER_SCATTERING_DUAL, MARSCHNER_MODE_LUT_PHYSICAL),
            (hp::compute::ShadeVariant{false, MARSCHNER_MODE_LUT_PHYSICAL | HAIR_FIBRE_DUAL}));
  EXPECT_EQ(variant(0, RENDER_SCATTERING_SINGLE, MARSCHNER_MODE_LUT_PHYSICAL),
            (hp::compute::ShadeVariant{false, MARSCHNER_MODE_LUT_PHYSICAL}));
  EXPECT_EQ(variant(3, RENDER_SCATTERING_DUAL, MARSCHNER_MODE_LUT_PHYSICAL).lightLoop, true);
  // Dual scattering belongs to the physical model: the others ignore the frame's choice, as at run time.
  for (std::uint32_t mode : {MARSCHNER_MODE_DIRECT, MARSCHNER_MODE_LUT_PAPER, MARSCHNER_MODE_LUT_FLOAT})
    EXPECT_EQ(variant(1, RENDER_SCATTERING_DUAL, mode).fibre, mode) << "mode " << mode;
  EXPECT_EQ(hairFibre(MARSCHNER_MODE_LUT_PHYSICAL, false), MARSCHNER_MODE_LUT_PHYSICAL);
  EXPECT_EQ(hairFibre(MARSCHNER_MODE_LUT_PHYSICAL, true) & HAIR_FIBRE_MODE_MASK, MARSCHNER_MODE_LUT_PHYSICAL);
}

TEST_F(VulkanTest, AFibreCompiledIntoTheShadePassShadesAsTheRunTimeForm) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kVariantExtent, kVariantFov);
  auto buffers = hp::test::makePixelStrands(*ctx, camera, kVariantExtent, fan(), 6);
  struct Case {
    hp::LutMode mode;
    hp::render::Scattering scattering;
    const char* name;
  };
  const Case cases[] = {{hp::LutMode::Direct, hp::render::Scattering::Dual, "direct"},
                        {hp::LutMode::Paper, hp::render::Scattering::Dual, "paper"},
                        {hp::LutMode::Float, hp::render::Scattering::Dual, "float"},
                        {hp::LutMode::Physical, hp::render::Scattering::Single, "physical, single"},
                        {hp::LutMode::Physical, hp::render::Scattering::Dual, "physical, dual"}};
  std::vector<std::vector<glm::vec4>> images;
  for (const Case& c : cases) {
    hp::render::LookSettings look;
    look.strandWidth = 2.0f * std::tan(0.5f * camera.fovY) / float(kVariantExtent.height);  // one pixel at unit depth
    look.scattering = c.scattering;
    hp::test::RasterRig rig(*ctx, *buffers, kVariantExtent, camera, look, hp::LightSpec{}, {}, c.mode);
    rig.run();
    const auto runTime = rig.image();
    const hp::compute::ShadeVariant variant = hp::compute::shadeVariantOf(rig.frame, rig.marschner.params());
    ASSERT_NE(variant.fibre, hp::gpu::HAIR_FIBRE_RUNTIME);
    // Not prepared yet: the pass falls back to the run-time fibre (and builds nothing).
    ASSERT_FALSE(rig.pass->shadingPrepared(variant)) << c.name;
    rig.rerunFine(std::span(&variant, 1));
    EXPECT_LE(compare(runTime, rig.image()).largest, kSame) << c.name << ": the fallback";
    EXPECT_FALSE(rig.pass->shadingPrepared(variant)) << c.name;
    rig.pass->prepareShading(variant);
    ASSERT_TRUE(rig.pass->shadingPrepared(variant)) << c.name;
    rig.rerunFine(std::span(&variant, 1));
    const Comparison d = compare(runTime, rig.image());
    std::cout << c.name << ": radiance total " << d.total << ", fixed fibre against run time " << d.largest << "\n";
    EXPECT_GT(d.total, 10.0) << c.name << ": the sun should light the fan";
    EXPECT_LE(d.largest, kSame) << c.name;
    images.push_back(runTime);
  }
  for (std::size_t a = 0; a < images.size(); ++a)
    for (std::size_t b = a + 1; b < images.size(); ++b)
      EXPECT_GT(compare(images[a], images[b]).largest, 10.0 * kSame) << cases[a].name << " against " << cases[b].name;
}
