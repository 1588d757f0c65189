// Filling the GPU block from a material + LUT.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.h"
#include "engine/core/shading/marschner_gpu.h"

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

// The physical block carries the multiple-scattering tables its LUT was built with (the same ones the M
// texture's back lobe came from), entry for entry; a physical LUT without them is refused by name; the other
// modes leave the tables zero.
TEST(MarschnerGpu, PhysicalBlockCarriesItsLutsMultipleScatteringTables) {
  HairMaterial m;
  m.absorption = {0.1, 0.2, 0.4};
  MarschnerLut lut = buildLut(LutMode::Physical, m);
  const gpu::MarschnerParams p = marschnerGpuParams(lut);
  const MultipleScatteringTables& t = lut.multipleScattering;
  ASSERT_EQ(t.backScatter.size(), gpu::MARSCHNER_SPREAD_ENTRIES);
  for (std::uint32_t k = 0; k < gpu::MARSCHNER_SPREAD_ENTRIES; ++k)
    for (int c = 0; c < 3; ++c) {
      EXPECT_FLOAT_EQ(p.forwardAlbedo[k][c], float(t.forwardAlbedo[k][c])) << k;
      EXPECT_FLOAT_EQ(p.backScatter[k][c], float(t.backScatter[k][c])) << k;
      EXPECT_FLOAT_EQ(p.meanTRT[k][c], float(t.meanTRT[k][c])) << k;
    }
  EXPECT_GT(p.backScatter[gpu::MARSCHNER_SPREAD_ENTRIES / 2].r, 0.0f);
  lut.multipleScattering = {};
  try {
    marschnerGpuParams(lut);
    ADD_FAILURE() << "a physical LUT without tables was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("without its multiple-scattering tables"), std::string::npos) << e.what();
  }
  EXPECT_EQ(marschnerGpuParams(buildLut(LutMode::Float, m)).backScatter[3], glm::vec4(0.0f));
}
