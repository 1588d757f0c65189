// MarschnerTextures on the device: image formats and contents, the device LUT lookup against the CPU
// emulation of the shader (texture upload, row order and the texel-centre convention), dummies for
// direct mode, and rebuilding only when the material or the mode changes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <iostream>

#include "engine/core/error.h"
#include "samples/tools/brdf_evaluator.h"
#include "compute/raster/marschner_textures.h"
#include "engine/core/shading/half_float.h"
#include "engine/core/shading/lut_sampler.h"
#include "engine/vk/transfer.h"
#include "tests/render/brdf_test_util.h"
#include "tests/support/vk_fixture.h"

using hp::LutMode;
using hp::render::MarschnerTextures;
using hp::test::VulkanTest;

namespace {
// Quantiles over samples and channels of |device - emulated| / (|emulated| + floor).
struct Agreement {
  double median = 0, p999 = 0, max = 0;
  std::size_t worst = 0;
};
Agreement agreement(const std::vector<glm::vec3>& device, const std::vector<glm::dvec3>& cpu, double floor) {
  std::vector<double> d;
  Agreement a;
  for (std::size_t i = 0; i < device.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      d.push_back(std::abs(double(device[i][c]) - cpu[i][c]) / (std::abs(cpu[i][c]) + floor));
      if (d.back() > a.max) {
        a.max = d.back();
        a.worst = i;
      }
    }
  std::sort(d.begin(), d.end());
  a.median = d[d.size() / 2];
  a.p999 = d[std::size_t(0.999 * double(d.size() - 1))];
  return a;
}

// lut_sampler's paper logic with the filtered RGBA8 result rounded to 8 bits, as llvmpipe's 8-bit
// texture path returns it (weightBits-bit weights).
glm::vec4 sample8(const hp::LutTexture& t, float u, float v, int weightBits) {
  glm::vec4 f = hp::sampleBilinear(t, u, v, {weightBits});
  return glm::round(f * 255.0f) / 255.0f * glm::vec4(t.scale[0], t.scale[1], t.scale[2], t.scale[3]);
}
std::vector<glm::dvec3> emulatePaper8(const hp::MarschnerLut& lut, const std::vector<hp::render::BrdfQuery>& q, int bits) {
  std::vector<glm::dvec3> out;
  for (const auto& r : q) {
    glm::vec4 ang = hp::gpu::marschnerAngles(r.L, r.V, r.T);
    glm::vec4 m = sample8(lut.textures[0], ang.x * 0.5f + 0.5f, ang.y * 0.5f + 0.5f, bits);
    glm::vec4 n = sample8(lut.textures[1], ang.z * 0.5f + 0.5f, m.w, bits);
    out.push_back(glm::dvec3((m.x * n.w + m.y * glm::vec3(n)) / std::max(m.w * m.w, 1e-6f)));
  }
  return out;
}

std::vector<glm::dvec3> emulate(const hp::MarschnerLut& lut, const std::vector<hp::render::BrdfQuery>& q, int bits) {
  std::vector<glm::dvec3> out;
  for (const auto& r : q)
    out.push_back(hp::evaluateLut(lut, glm::dvec3(r.L), glm::dvec3(r.V), glm::dvec3(r.T), {bits}));
  return out;
}
}  // namespace

TEST_F(VulkanTest, MarschnerTexturesHaveTheLutSizesAndFormats) {
  MarschnerTextures paper(*ctx, hp::HairMaterial{}, LutMode::Paper);
  EXPECT_EQ(paper.slotImage(0).desc().format, VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_EQ(paper.slotImage(0).desc().width, 128u);
  EXPECT_EQ(paper.slotImage(1).desc().height, 128u);
  EXPECT_EQ(paper.slotImage(2).desc().width, 1u) << "paper has no N1: the dummy";
  MarschnerTextures flt(*ctx, hp::HairMaterial{}, LutMode::Float);
  for (std::uint32_t s = 0; s < 3; ++s) EXPECT_EQ(flt.slotImage(s).desc().format, VK_FORMAT_R16G16B16A16_SFLOAT);
  EXPECT_EQ(flt.slotImage(0).desc().width, hp::gpu::MARSCHNER_FLOAT_M_WIDTH);
  EXPECT_EQ(flt.slotImage(1).desc().width, hp::gpu::MARSCHNER_FLOAT_N_WIDTH);
  EXPECT_EQ(flt.slotImage(2).desc().height, hp::gpu::MARSCHNER_FLOAT_N_HEIGHT);
  MarschnerTextures direct(*ctx, hp::HairMaterial{}, LutMode::Direct);
  EXPECT_EQ(direct.mode(), LutMode::Direct);
  EXPECT_TRUE(direct.lut().textures.empty());
  for (std::uint32_t s = 0; s < 3; ++s) EXPECT_EQ(direct.slotImage(s).desc().width, 1u);
  EXPECT_EQ(direct.params().control.x, hp::gpu::MARSCHNER_MODE_DIRECT);
  EXPECT_THROW(direct.slotImage(3), hp::Error);
}

TEST_F(VulkanTest, MarschnerTexturesHoldTheCpuTexelsBitForBit) {
  MarschnerTextures flt(*ctx, hp::HairMaterial{}, LutMode::Float);
  const hp::LutTexture& n0 = flt.lut().textures[1];
  auto bytes = hp::vk::readbackImage(*ctx, flt.slotImage(1), hp::vk::ImageUse::ComputeSampled);
  ASSERT_EQ(bytes.size(), n0.data.size() * 2);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n0.data.size(); ++i) {
    std::uint16_t h;
    std::memcpy(&h, &bytes[i * 2], 2);
    mismatches += hp::shading::halfToFloat(h) != n0.data[i];
  }
  EXPECT_EQ(mismatches, 0u);

  MarschnerTextures paper(*ctx, hp::HairMaterial{}, LutMode::Paper);
  const hp::LutTexture& m = paper.lut().textures[0];
  auto m8 = hp::vk::readbackImage(*ctx, paper.slotImage(0), hp::vk::ImageUse::ComputeSampled);
  ASSERT_EQ(m8.size(), m.data.size());
  mismatches = 0;
  for (std::size_t i = 0; i < m.data.size(); ++i) mismatches += float(std::uint8_t(m8[i])) / 255.0f != m.data[i];
  EXPECT_EQ(mismatches, 0u);
}

// The device's filtered lookups agree with lut_sampler's emulation, which proves the upload, the row
// order and the texel-centre convention (half a texel off would move the median to percents).
// Float mode (RGBA16F): lavapipe filters in float, so most samples agree bit for bit; the tail comes
// from float rounding of the coordinates where S is steep (|theta_d| near 90 deg).
// Paper mode (RGBA8): lavapipe's 8-bit texture path returns the FILTERED value rounded to 8 bits
// (measured: the plain emulation is off by a median 0.11%, with that rounding by 0), and paper mode
// feeds M.a into the N lookup and divides by its square, so the tail is wider.
TEST_F(VulkanTest, DeviceLutLookupAgreesWithTheCpuEmulation) {
  const auto queries = hp::test::randomQueries(20'000, 7);
  hp::render::BrdfEvaluator evaluator(*ctx);
  auto report = [&](const char* what, const Agreement& a) {
    const auto& w = queries[a.worst];
    std::cout << what << ": |device - emulated| / (|emulated| + 0.01): median " << a.median << ", p99.9 " << a.p999
              << ", max " << a.max << " at L=(" << w.L.x << "," << w.L.y << "," << w.L.z << ") V=(" << w.V.x << ","
              << w.V.y << "," << w.V.z << ") T=(" << w.T.x << "," << w.T.y << "," << w.T.z << ")\n";
    return a;
  };

  // The median bound (1e-6) holds the device to an exact emulation of lavapipe's filter (exact weights; RGBA8
  // results rounded to 8 bits): it applies where the device is lavapipe. Other conformant devices may quantise
  // the filter weights to subTexelPrecisionBits and evaluate the shader's arithmetic to Vulkan's looser
  // precision (an NVIDIA H100, driver 580: median 2.2e-5 float and 1.6e-5 paper against the plain emulation,
  // where one 8-bit weight step moves the float median by only 2.3e-6); they are held to the p99.9 and max
  // bounds.
  const bool lavapipe = std::string(ctx->properties().deviceName).find("llvmpipe") != std::string::npos;
  MarschnerTextures flt(*ctx, hp::HairMaterial{}, LutMode::Float);
  Agreement f = report("float", agreement(evaluator.evaluate(flt, queries), emulate(flt.lut(), queries, 0), 0.01));
  if (lavapipe) {
    EXPECT_LE(f.median, 1e-6);
  }
  EXPECT_LE(f.p999, 1e-3);
  EXPECT_LE(f.max, 0.05);

  MarschnerTextures paper(*ctx, hp::HairMaterial{}, LutMode::Paper);
  std::vector<glm::vec3> device = evaluator.evaluate(paper, queries);
  Agreement plain = report("paper, plain emulation", agreement(device, emulate(paper.lut(), queries, 0), 0.01));
  Agreement p = report("paper, filtered result rounded to 8 bits",
                       agreement(device, emulatePaper8(paper.lut(), queries, 8), 0.01));
  if (lavapipe) {
    EXPECT_LE(p.median, 1e-6);
  }
  EXPECT_LE((lavapipe ? p : plain).p999, 0.25);
}

TEST_F(VulkanTest, MarschnerTexturesRebuildOnlyWhenMaterialOrModeChanges) {
  const auto queries = hp::test::randomQueries(2'000, 11);
  hp::render::BrdfEvaluator evaluator(*ctx);
  hp::HairMaterial brown;
  MarschnerTextures textures(*ctx, brown, LutMode::Float);
  EXPECT_EQ(textures.buildCount(), 1u);
  const VkImageView viewBefore = textures.slotImage(1).view();
  std::vector<glm::vec3> before = evaluator.evaluate(textures, queries);

  EXPECT_FALSE(textures.rebuild(brown, LutMode::Float));
  EXPECT_EQ(textures.buildCount(), 1u);

  hp::HairMaterial blonde = brown;
  blonde.absorption = {0.06, 0.1, 0.2};
  EXPECT_TRUE(textures.rebuild(blonde, LutMode::Float));
  EXPECT_EQ(textures.buildCount(), 2u);
  EXPECT_EQ(textures.material(), blonde);
  EXPECT_EQ(textures.slotImage(1).view(), viewBefore) << "same mode: images are refilled in place";
  std::vector<glm::vec3> after = evaluator.evaluate(textures, queries);
  // Less absorption: more light through TT and TRT, so S grows, most in blue; R is unchanged.
  double sumBefore = 0, sumAfter = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    sumBefore += before[i].b;
    sumAfter += after[i].b;
  }
  EXPECT_GT(sumAfter, 2.0 * sumBefore);
  // And matches a fresh build for that material.
  MarschnerTextures fresh(*ctx, blonde, LutMode::Float);
  EXPECT_EQ(evaluator.evaluate(fresh, queries), after);

  EXPECT_TRUE(textures.rebuild(blonde, LutMode::Paper));
  EXPECT_EQ(textures.mode(), LutMode::Paper);
  EXPECT_EQ(textures.slotImage(0).desc().format, VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_TRUE(textures.rebuild(blonde, LutMode::Direct));
  EXPECT_EQ(textures.buildCount(), 4u);

  hp::HairMaterial bad = blonde;
  bad.eta = 0.5;
  EXPECT_THROW(textures.rebuild(bad, LutMode::Float), hp::Error);
  EXPECT_EQ(textures.mode(), LutMode::Direct) << "a failed rebuild keeps the old state";
  EXPECT_EQ(textures.material(), blonde);
  EXPECT_EQ(textures.buildCount(), 4u);
}

TEST_F(VulkanTest, MarschnerTexturesRefuseAnInvalidMaterial) {
  hp::HairMaterial bad;
  bad.betaR = -1.0;
  try {
    MarschnerTextures textures(*ctx, bad, LutMode::Paper);
    FAIL() << "expected hp::Error";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("betaR"), std::string::npos) << e.what();
  }
}
