// LUT construction, the bilinear sampler emulation, half floats and the shared parameterisation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/tools/host/lut_export.h"
#include "engine/core/shading/half_float.h"
#include "engine/core/shading/lut.h"
#include "engine/core/shading/lut_sampler.h"
#include "engine/core/shading/marschner_terms.h"
#include "shaders/shared/marschner.h"

using namespace hp;

namespace {
LutTexture ramp(std::uint32_t w, std::uint32_t h) {
  LutTexture t;
  t.width = w;
  t.height = h;
  t.data.resize(std::size_t(w) * h * 4);
  for (std::uint32_t j = 0; j < h; ++j)
    for (std::uint32_t i = 0; i < w; ++i) {
      float* p = t.texel(i, j);
      p[0] = float(i);
      p[1] = float(j);
      p[2] = float(i * j);
      p[3] = 1.0f;
    }
  return t;
}
}  // namespace

TEST(LutSampler, TexelCentresReturnTexelsExactly) {
  LutTexture t = ramp(8, 4);
  glm::vec4 v = sampleBilinear(t, 3.5f / 8, 2.5f / 4);
  EXPECT_EQ(v, glm::vec4(3, 2, 6, 1));
}

TEST(LutSampler, BilinearBetweenCentresAndClampToEdge) {
  LutTexture t = ramp(8, 4);
  glm::vec4 v = sampleBilinear(t, 4.0f / 8, 1.25f / 4);  // x halfway 3..4, y quarter 0..1
  EXPECT_FLOAT_EQ(v.x, 3.5f);
  EXPECT_FLOAT_EQ(v.y, 0.75f);
  EXPECT_EQ(sampleBilinear(t, -0.3f, 0.0f).x, 0.0f);  // left of the first centre: clamped
  EXPECT_EQ(sampleBilinear(t, 1.0f, 1.0f), glm::vec4(7, 3, 21, 1));
  LutSamplerOptions o;
  o.subTexelBits = 2;  // weights snap to quarters
  EXPECT_FLOAT_EQ(sampleBilinear(t, (3.5f + 0.3f) / 8, 0.5f / 4, o).x, 3.25f);
}

TEST(HalfFloat, RoundTripsAndRounds) {
  for (float x : {0.0f, 1.0f, -2.5f, 65504.0f, 6.103515625e-05f, 5.9604644775390625e-08f})
    EXPECT_EQ(shading::roundToHalf(x), x) << x;
  EXPECT_EQ(shading::floatToHalf(1.0f), 0x3c00);
  EXPECT_EQ(shading::roundToHalf(1.0f + 1.0f / 2048), 1.0f);  // ties to even (ulp 1/1024)
  EXPECT_EQ(shading::roundToHalf(1.0f + 3.0f / 2048), 1.0f + 1.0f / 512);
  EXPECT_TRUE(std::isinf(shading::roundToHalf(70000.0f)));
  EXPECT_NEAR(shading::roundToHalf(0.1234567f), 0.1234567f, 0.1234567f / 2048);
}

TEST(LutParam, ForwardAndInverseAgreeWithTheShaderFormula) {
  for (double a = 0.0; a <= std::numbers::pi / 2; a += 0.01) {
    double x = shading::pseudoAngle(a);
    EXPECT_NEAR(shading::pseudoAngleInverse(x), a, 1e-9);
    EXPECT_NEAR(gpu::marschnerPseudoAngle(float(std::cos(2 * a))), x, 2e-4);  // float, from cos 2a
  }
  EXPECT_NEAR(shading::pseudoAngle(std::numbers::pi / 4), 0.5, 1e-15);
}

TEST(LutParam, ShaderCoordinatesHitTexelCentres) {
  // theta_d = 0, phi = pi: N v at texel 0 centre, N u at the last texel centre.
  glm::vec4 c = gpu::marschnerFloatCoords(glm::vec4(0.2f, 0.2f, -1.0f, 0.0f));
  EXPECT_NEAR(c.y, (gpu::MARSCHNER_FLOAT_N_WIDTH - 0.5f) / gpu::MARSCHNER_FLOAT_N_WIDTH, 1e-6);
  EXPECT_NEAR(c.z, 0.5f / gpu::MARSCHNER_FLOAT_N_HEIGHT, 1e-3f / gpu::MARSCHNER_FLOAT_N_HEIGHT);
  EXPECT_NEAR(c.w, 1.0f, 1e-6);
}

TEST(Lut, FloatTexturesHoldTheLobesAtTexelCentres) {
  HairMaterial m;
  MarschnerLut lut = buildLut(LutMode::Float, m);
  ASSERT_EQ(lut.textures.size(), 3u);
  const LutTexture& n0 = lut.textures[1];
  EXPECT_EQ(n0.format, LutFormat::RGBA16F);
  std::uint32_t i = 100, j = 40;
  double phi = 2 * shading::pseudoAngleInverse(shading::texelCentre(i, n0.width));
  double td = shading::pseudoAngleInverse(shading::texelCentre(j, n0.height));
  EXPECT_NEAR(n0.texel(i, j)[3], shading::lobeNR(phi, td, m), 1e-3 * shading::lobeNR(phi, td, m));
  EXPECT_NEAR(n0.texel(i, j)[0], shading::lobeNTT(phi, td, m).r, 1e-3 * shading::lobeNTT(phi, td, m).r + 1e-7);
}

TEST(Lut, PaperTexturesAreUnorm8WithScales) {
  MarschnerLut lut = buildLut(LutMode::Paper, HairMaterial{});
  ASSERT_EQ(lut.textures.size(), 2u);
  for (const LutTexture& t : lut.textures) {
    EXPECT_EQ(t.width, 128u);
    EXPECT_EQ(t.height, 128u);
    for (float v : t.data) {
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
      ASSERT_FLOAT_EQ(std::nearbyint(v * 255.0f), v * 255.0f);
    }
  }
  EXPECT_EQ(lut.textures[0].scale[3], 1.0f);  // cos theta_d is stored as is
  EXPECT_GT(lut.textures[0].scale[1], 1.0f);  // M_TT peaks above 1
}

TEST(Lut, JsonDescribesLayoutAndScales) {
  nlohmann::json j = describeLut(buildLut(LutMode::Paper, HairMaterial{}));
  EXPECT_EQ(j["mode"], "paper");
  EXPECT_EQ(j["textures"][0]["format"], "R8G8B8A8_UNORM");
  EXPECT_EQ(j["textures"][1]["channels"][3], "N_R");
  EXPECT_EQ(j["textures"][0]["scale"].size(), 4u);
  EXPECT_TRUE(describeLut(buildLut(LutMode::Direct, HairMaterial{}))["textures"].empty());
  EXPECT_EQ(parseLutMode("float"), LutMode::Float);
  EXPECT_THROW(parseLutMode("bogus"), hp::Error);
}
