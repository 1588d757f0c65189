// Filling the GPU block from a material + LUT.
#include <gtest/gtest.h>

#include "engine/shading/marschner_gpu.h"

using namespace hp;

TEST(MarschnerGpu, CarriesMaterialModeAndScales) {
  HairMaterial m;
  m.eta = 1.6;
  MarschnerLut paper = buildLut(LutMode::Paper, m);
  gpu::MarschnerParams p = marschnerGpuParams(paper);
  EXPECT_FLOAT_EQ(p.absorption.w, 1.6f);
  EXPECT_FLOAT_EQ(p.absorption.y, 0.91f);
  EXPECT_FLOAT_EQ(p.longitudinal.y, float(m.betaR));
  EXPECT_FLOAT_EQ(p.caustic.y, 0.5f);
  EXPECT_EQ(p.control.x, gpu::MARSCHNER_MODE_LUT_PAPER);
  EXPECT_EQ(p.mScale.y, paper.textures[0].scale[1]);
  EXPECT_EQ(p.n0Scale.w, paper.textures[1].scale[3]);
  EXPECT_EQ(p.n1Scale, glm::vec4(1.0f));
  EXPECT_EQ(marschnerGpuParams(buildLut(LutMode::Float, m)).control.x, gpu::MARSCHNER_MODE_LUT_FLOAT);
  EXPECT_EQ(marschnerGpuParams(buildLut(LutMode::Direct, m)).control.x, gpu::MARSCHNER_MODE_DIRECT);
}
