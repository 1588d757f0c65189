// Guide growth (paper §1): roots, directions, the geometric segment law, lengths, determinism.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/hair/guide_growth.h"
#include "engine/core/hair/segment_profile.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
// Two triangles with distinct, tilted normals.
ScalpMesh twoTriangleScalp() {
  std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0.2f}, {1, 1, 0.5f}};
  std::vector<glm::vec3> n{{0, 0, 1}, {0.3f, 0, 1}, {0, -0.2f, 1}, {1, 1, 1}};
  return buildScalpMesh(p, {{0, 1, 2}, {1, 3, 2}}, n);
}

TEST(GrowthSegments, GrowByTheRatioAndSumToTheTotal) {
  auto l = geometricSegmentLengths(0.6f, 1.25f, 6);
  ASSERT_EQ(l.size(), 6u);
  float sum = 0.0f;
  for (std::size_t k = 0; k < l.size(); ++k) {
    sum += l[k];
    if (k > 0) {
      EXPECT_NEAR(l[k] / l[k - 1], 1.25f, 1e-5f);
    }
  }
  EXPECT_NEAR(sum, 0.6f, 1e-6f);
  auto s = geometricArcPositions(0.6f, 1.25f, 6);
  EXPECT_EQ(s.front(), 0.0f);
  EXPECT_EQ(s.back(), 0.6f);
}

TEST(GrowthSegments, RejectsBadArguments) {
  EXPECT_ERROR_CONTAINS(geometricSegmentLengths(1.0f, 1.2f, 0), "at least one segment");
  EXPECT_ERROR_CONTAINS(geometricSegmentLengths(-1.0f, 1.2f, 3), "total length must be positive");
  EXPECT_ERROR_CONTAINS(geometricSegmentLengths(1.0f, 0.5f, 3), "segment ratio must be in [1, 4]");
}

TEST(Growth, RootAtVertexAlongNormalWithIncreasingSegments) {
  ScalpMesh scalp = twoTriangleScalp();
  GrowthOptions o;
  o.length = 0.5f;
  o.lengthVariation = 0.2f;
  o.segmentRatio = 1.4f;
  GuideSet guides = growGuides(scalp, o);
  ASSERT_EQ(guides.guideCount(), 4u);
  ASSERT_EQ(guides.particlesPerGuide, 7u);
  for (std::uint32_t g = 0; g < 4; ++g) {
    auto guide = guides.guide(g);
    EXPECT_EQ(guide[0], scalp.positions[g]);
    float total = 0.0f, previous = 0.0f;
    for (std::uint32_t k = 1; k < 7; ++k) {
      glm::vec3 d = guide[k] - guide[k - 1];
      float len = glm::length(d);
      EXPECT_NEAR(glm::dot(d / len, scalp.normals[g]), 1.0f, 1e-5f) << "guide " << g << " segment " << k;
      if (k > 1) {
        EXPECT_GT(len, previous);
        EXPECT_NEAR(len / previous, 1.4f, 1e-3f);
      }
      previous = len;
      total += len;
    }
    EXPECT_NEAR(total, grownGuideLength(o, g), 1e-5f);
    EXPECT_GE(grownGuideLength(o, g), 0.5f * 0.8f);
    EXPECT_LE(grownGuideLength(o, g), 0.5f * 1.2f);
  }
}

TEST(Growth, LengthVariationIsSeededAndDeterministic) {
  GrowthOptions a, b;
  b.seed = 99;
  bool differs = false;
  for (std::uint32_t g = 0; g < 16; ++g) {
    EXPECT_EQ(grownGuideLength(a, g), grownGuideLength(a, g));
    differs |= grownGuideLength(a, g) != grownGuideLength(b, g);
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(growGuides(twoTriangleScalp(), a).positions, growGuides(twoTriangleScalp(), a).positions);
}

TEST(Growth, SupportsTwoToSixtyFourParticles) {
  for (std::uint32_t p : {2u, 7u, 64u}) {
    GrowthOptions o;
    o.particlesPerGuide = p;
    GuideSet g = growGuides(twoTriangleScalp(), o);
    EXPECT_EQ(g.positions.size(), 4u * p);
  }
  GrowthOptions o;
  o.particlesPerGuide = 65;
  EXPECT_ERROR_CONTAINS(growGuides(twoTriangleScalp(), o), "particles per guide must be in [2, 64], got 65");
  o.particlesPerGuide = 1;
  EXPECT_ERROR_CONTAINS(growGuides(twoTriangleScalp(), o), "got 1");
}

TEST(Growth, RejectsBadOptions) {
  GrowthOptions o;
  o.length = 0.0f;
  EXPECT_ERROR_CONTAINS(o.validate(), "length must be in [0.0001, 10000]");
  o.length = 1e-30f;  // positive, and every particle NaN a frame later
  EXPECT_ERROR_CONTAINS(o.validate(), "length must be in [0.0001, 10000]");
  o = {};
  o.lengthVariation = 1.0f;
  EXPECT_ERROR_CONTAINS(o.validate(), "lengthVariation must be in [0, 1)");
  o = {};
  o.bend = 1.5f;
  EXPECT_ERROR_CONTAINS(o.validate(), "bend must be in [0, 1]");
  o = {};
  o.bendDirection = glm::vec3(0.0f);
  EXPECT_ERROR_CONTAINS(o.validate(), "bendDirection must be a non-zero vector");
}

TEST(Growth, BendTurnsLaterSegmentsTowardGravityKeepingLengths) {
  ScalpMesh scalp = buildScalpMesh({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 2, 1}}, {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}});
  GrowthOptions straight, bent;
  bent.bend = 0.4f;
  GuideSet s = growGuides(scalp, straight), b = growGuides(scalp, bent);
  auto gs = s.guide(0), gb = b.guide(0);
  EXPECT_EQ(gb[1], gs[1]);  // first segment still along the normal
  float previousY = 0.0f;
  for (std::uint32_t k = 2; k < 7; ++k) {
    glm::vec3 d = glm::normalize(gb[k] - gb[k - 1]);
    EXPECT_LT(d.y, previousY);  // ever more downward
    previousY = d.y;
    EXPECT_NEAR(glm::length(gb[k] - gb[k - 1]), glm::length(gs[k] - gs[k - 1]), 1e-5f);
  }
}

TEST(Growth, CollidersKeepParticlesOutsideAndLengthsExact) {
  // A vertex on top of a sphere with its normal pointing sideways: bending down would enter the sphere.
  ScalpMesh scalp = buildScalpMesh({{0, 1, 0}, {0.1f, 1, 0}, {0, 1, 0.1f}}, {{0, 2, 1}},
                                   {{1, 0.2f, 0}, {1, 0.2f, 0}, {1, 0.2f, 0}});
  std::vector<SphereCollider> colliders{{{0, 0, 0}, 1.0f}};
  GrowthOptions o;
  o.bend = 0.6f;
  o.length = 3.0f;
  o.lengthVariation = 0.0f;
  GuideSet g = growGuides(scalp, o, colliders);
  auto lengths = geometricSegmentLengths(3.0f, o.segmentRatio, 6);
  for (std::uint32_t i = 0; i < g.guideCount(); ++i)
    for (std::uint32_t k = 1; k < 7; ++k) {
      EXPECT_GE(glm::length(g.guide(i)[k]), 1.0f - 1e-3f) << "guide " << i << " particle " << k;
      EXPECT_NEAR(glm::length(g.guide(i)[k] - g.guide(i)[k - 1]), lengths[k - 1], 1e-4f);
    }
}
}  // namespace
}  // namespace hp
