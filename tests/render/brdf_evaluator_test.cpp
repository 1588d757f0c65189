// BrdfEvaluator: chunking (results independent of the chunk size, order preserved), the storage-range
// limit, one million rows, and the empty case.
#include <gtest/gtest.h>

#include <chrono>
#include <iostream>

#include "engine/core/error.h"
#include "samples/tools/brdf_evaluator.h"
#include "compute/raster/marschner_textures.h"
#include "engine/core/shading/lut_sampler.h"
#include "engine/core/shading/marschner.h"
#include "shaders/shared/brdf_eval.h"
#include "tests/render/brdf_test_util.h"
#include "tests/support/vk_fixture.h"

using hp::LutMode;
using hp::render::BrdfEvaluator;
using hp::render::MarschnerTextures;
using hp::test::VulkanTest;

TEST_F(VulkanTest, BrdfEvaluatorResultsDoNotDependOnTheChunkSize) {
  const auto queries = hp::test::randomQueries(2'500, 5);
  MarschnerTextures textures(*ctx, hp::HairMaterial{}, LutMode::Direct);
  BrdfEvaluator whole(*ctx);
  BrdfEvaluator chunked(*ctx, 300);  // 9 chunks, the last one partial
  EXPECT_EQ(chunked.rowsPerChunk(), 300u);
  std::vector<glm::vec3> a = whole.evaluate(textures, queries);
  std::vector<glm::vec3> b = chunked.evaluate(textures, queries);
  ASSERT_EQ(a.size(), queries.size());
  EXPECT_EQ(a, b);
  // Row order: each row against the exact S of that row.
  for (std::size_t i = 0; i < queries.size(); i += 97) {
    glm::dvec3 exact = hp::marschnerS(glm::dvec3(queries[i].L), glm::dvec3(queries[i].V), glm::dvec3(queries[i].T), {});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(b[i][c], exact[c], 1e-3 * (exact[c] + 0.01)) << "row " << i;
  }
  EXPECT_TRUE(whole.evaluate(textures, {}).empty());
}

TEST_F(VulkanTest, BrdfEvaluatorChunksFitTheStorageBufferRange) {
  BrdfEvaluator evaluator(*ctx, 0xFFFFFFFFu);
  const std::uint64_t range = ctx->properties().limits.maxStorageBufferRange;
  EXPECT_LE(std::uint64_t(evaluator.rowsPerChunk()) * sizeof(hp::gpu::BrdfEvalInput), range);
  EXPECT_GT(std::uint64_t(evaluator.rowsPerChunk() + 1) * sizeof(hp::gpu::BrdfEvalInput), range);
  EXPECT_THROW(BrdfEvaluator(*ctx, 0), hp::Error);
}

// One million rows (paper mode, the cheapest kernel) in 4 chunks: every row comes back in order.
TEST_F(VulkanTest, BrdfEvaluatorHandlesOneMillionRows) {
  const std::size_t n = 1'000'000;
  const auto distinct = hp::test::randomQueries(1'000, 9);
  std::vector<hp::render::BrdfQuery> queries(n);
  for (std::size_t i = 0; i < n; ++i) queries[i] = distinct[(i * 7919) % distinct.size()];
  MarschnerTextures textures(*ctx, hp::HairMaterial{}, LutMode::Paper);
  BrdfEvaluator evaluator(*ctx, 1u << 18);
  auto t0 = std::chrono::steady_clock::now();
  std::vector<glm::vec3> s = evaluator.evaluate(textures, queries);
  auto ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  std::cout << n << " rows in " << ms << " ms\n";
  ASSERT_EQ(s.size(), n);
  std::vector<glm::vec3> reference = evaluator.evaluate(textures, distinct);
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < n; ++i) mismatches += s[i] != reference[(i * 7919) % distinct.size()];
  EXPECT_EQ(mismatches, 0u);
}
