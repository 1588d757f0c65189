// The process's shared Marschner tables (engine/core/shading/lut_cache.h): built once for the same mode,
// material and options, equal to a fresh build, apart for anything else; a bad material refused each time.
#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/core/shading/lut_cache.h"

using namespace hp;

TEST(LutCache, TheSameTablesAreBuiltOnceAndEqualAFreshBuild) {
  HairMaterial material;
  material.betaR = 0.13;  // a material no other test in this process asks for
  const auto first = sharedLut(LutMode::Float, material);
  EXPECT_EQ(sharedLut(LutMode::Float, material), first) << "the second request builds again";
  const MarschnerLut fresh = buildLut(LutMode::Float, material);
  ASSERT_EQ(first->textures.size(), fresh.textures.size());
  for (std::size_t t = 0; t < fresh.textures.size(); ++t) EXPECT_EQ(first->textures[t].data, fresh.textures[t].data);
  // Anything that changes the tables gets its own.
  HairMaterial other = material;
  other.betaR = 0.14;
  EXPECT_NE(sharedLut(LutMode::Float, other), first);
  EXPECT_NE(sharedLut(LutMode::Paper, material), first);
  LutBuildOptions options;
  options.floatFormat = LutFormat::RGBA32F;
  EXPECT_NE(sharedLut(LutMode::Float, material, options), first);
}

TEST(LutCache, ABadMaterialIsRefusedEveryTimeItIsAskedFor) {
  HairMaterial bad;
  bad.betaR = -1.0;
  EXPECT_THROW(sharedLut(LutMode::Physical, bad), Error);
  EXPECT_THROW(sharedLut(LutMode::Physical, bad), Error);  // not remembered as built
}
