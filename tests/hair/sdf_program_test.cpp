// Distance programs (engine/core/hair/sdf_program.h) and the narrow-band sampling built on them: a program
// specialised to a box gives the whole program's value bit for bit inside the box and its bounds hold
// every value there; the narrow band holds the exact field near the surface and the right sign beyond.
#include <gtest/gtest.h>

#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/head_sdf.h"
#include "engine/core/hair/level_set_mesh.h"
#include "engine/core/hair/narrow_band.h"
#include "engine/core/hair/rng.h"
#include "engine/core/hair/sdf_primitives.h"
#include "engine/core/hair/sdf_program.h"

namespace hp {
namespace {
glm::vec3 random3(std::uint32_t index, std::uint32_t stream) {
  return {hashRandom(11, index, stream), hashRandom(11, index, stream + 1), hashRandom(11, index, stream + 2)};
}
}  // namespace

TEST(SdfProgram, SpecialisedToABoxItIsTheWholeFieldThereAndBoundsIt) {
  const sdf::Program& head = headField();
  std::size_t pruned = 0, points = 0;
  for (std::uint32_t b = 0; b < 400; ++b) {
    // Boxes of 2 mm to 13 cm anywhere around the head, some straddling the mirror plane x = 0.
    const glm::vec3 size = glm::vec3(0.002f) + 0.13f * random3(b, 0) * random3(b, 3);
    const glm::vec3 lo = kHeadFieldLow + (kHeadFieldHigh - kHeadFieldLow - size) * random3(b, 6);
    sdf::Interval range;
    const sdf::Program p = head.specialise(lo, lo + size, &range);
    pruned += head.leaves() - p.leaves();
    for (std::uint32_t i = 0; i < 40; ++i, ++points) {
      const glm::vec3 x = lo + size * random3(b * 64 + i, 9);
      const float whole = head(x);
      ASSERT_EQ(p(x), whole) << "box " << b << " point " << i;
      ASSERT_GE(whole, range.lo);
      ASSERT_LE(whole, range.hi);
    }
  }
  EXPECT_GT(pruned, 400u * head.leaves() * 2 / 5);  // boxes up to 13 cm: still ~half of the leaves drop out
}

// evaluate() re-spells every primitive over arrays so that it vectorises (sdf_program.cpp); it must
// give operator()'s float bit for bit, for every kind of leaf the head uses (mirrored ones included).
TEST(SdfProgram, BatchEvaluationIsThePointwiseValueBitForBit) {
  const sdf::Program& head = headField();
  std::vector<glm::vec3> points(1000);  // not a multiple of the batch: the last batch is partial
  for (std::uint32_t i = 0; i < points.size(); ++i)
    points[i] = kHeadFieldLow + (kHeadFieldHigh - kHeadFieldLow) * random3(i, 20);
  std::vector<float> batch(points.size());
  head.evaluate(points, batch);
  for (std::size_t i = 0; i < points.size(); ++i) ASSERT_EQ(batch[i], head(points[i])) << "point " << i;
}

TEST(SdfProgram, BlendsFollowThePrimitives) {
  sdf::Program p;
  p.sphere({0, 0, 0}, 1.0f).sphere({1.5f, 0, 0}, 1.0f).smoothUnion(0.2f).belowPlaneY(-0.5f).max();
  for (const glm::vec3 x : {glm::vec3(0.3f, 0.2f, 0.1f), glm::vec3(0.75f, 0.9f, 0.0f), glm::vec3(2, -2, 1)})
    EXPECT_EQ(p(x), std::max(sdf::smoothUnion(sdf::sphere(x, {0, 0, 0}, 1.0f), sdf::sphere(x, {1.5f, 0, 0}, 1.0f), 0.2f),
                             -0.5f - x.y));
  EXPECT_THROW(sdf::Program().sphere({0, 0, 0}, 1.0f).smoothUnion(0.1f), Error);  // one value below the blend
  EXPECT_THROW(sdf::Program().ellipsoid({0, 0, 0}, {1.0f, 0.0f, 1.0f}), Error);
}

TEST(SdfProgram, NarrowBandOfABallMeshesLikeTheWholeGrid) {
  sdf::Program ball;
  ball.sphere({0.01f, -0.02f, 0.0f}, 0.5f);
  const NarrowBandGrid band = sampleNarrowBand(ball, glm::vec3(-0.7f), glm::vec3(0.7f), 0.02f, 0.05f);
  const SdfGrid whole = sampleField([&](const glm::vec3& p) { return ball(p); }, glm::vec3(-0.7f), glm::vec3(0.7f), 0.02f);
  ASSERT_EQ(band.grid.dims, whole.dims);
  EXPECT_LT(band.exactNodes, whole.values.size() / 2);
  const HeadMesh a = meshZeroLevel(band.grid, band.band), b = meshZeroLevel(whole, [&](const glm::vec3& p) { return ball(p); });
  EXPECT_EQ(a.indices.size(), b.indices.size());
  EXPECT_EQ(a.positions.size(), b.positions.size());
  EXPECT_THROW(sampleNarrowBand(ball, glm::vec3(-0.7f), glm::vec3(0.7f), 0.02f, 0.0f), Error);
  // Every second node (a render mesh coarser than the collider): the same on both grids, about a
  // quarter of the triangles, vertices still on the exact surface; a stride must divide the brick.
  const HeadMesh c = meshZeroLevel(band.grid, band.band, 2);
  const HeadMesh d = meshZeroLevel(whole, wholeGridBand(whole, [&](const glm::vec3& p) { return ball(p); }), 2);
  EXPECT_EQ(c.indices.size(), d.indices.size());
  EXPECT_GT(c.indices.size(), a.indices.size() / 6);
  EXPECT_LT(c.indices.size(), a.indices.size() / 3);
  for (const glm::vec3& p : c.positions) ASSERT_LT(std::abs(ball(p)), 1e-5f);
  EXPECT_THROW(meshZeroLevel(band.grid, band.band, 3), Error);
}
}  // namespace hp
