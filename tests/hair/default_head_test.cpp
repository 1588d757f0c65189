// The procedural default head: scalp size and place, the field as the collider, a rest pose that
// hangs like hair, and a usable interpolation topology.
#include <gtest/gtest.h>

#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_sdf.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
const HairAsset& asset() {
  static const HairAsset a = buildDefaultHeadAsset();
  return a;
}

// > 0: inside the head's field (the analytic one, not the grid).
float insideDepth(const glm::vec3& p) { return -headDistance(p); }

TEST(DefaultHead, ScalpHasOneToFourThousandVerticesAndOneGuideEach) {
  ScalpMesh scalp = makeDefaultScalp();
  EXPECT_GE(scalp.vertexCount(), 1000u);
  EXPECT_LE(scalp.vertexCount(), 4000u);
  EXPECT_EQ(asset().guides.guideCount(), scalp.vertexCount());
  EXPECT_EQ(asset().guides.particlesPerGuide, 7u);
  EXPECT_EQ(asset().topology.triangles, scalp.triangles);
  EXPECT_EQ(asset().name, "default head");
}

TEST(DefaultHead, ScalpCoversCrownBackAndSidesButNotTheFace) {
  ScalpMesh scalp = makeDefaultScalp();
  bool crown = false, back = false, left = false, right = false;
  for (const auto& p : scalp.positions) {
    crown |= p.y > 0.085f;
    back |= p.z < -0.10f;
    left |= p.x < -0.068f;
    right |= p.x > 0.068f;
    EXPECT_FALSE(p.z > 0.05f && p.y < 0.02f) << "scalp vertex on the face at " << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_TRUE(crown && back && left && right);
}

TEST(DefaultHead, TheFieldIsTheColliderAndTheMeshIsItsSurface) {
  const auto& a = asset();
  EXPECT_TRUE(a.colliders.empty());
  ASSERT_TRUE(a.sdf);
  EXPECT_EQ(a.sdf->cell, kDefaultHeadCell);
  ASSERT_EQ(a.head.positions.size(), a.head.normals.size());
  ASSERT_EQ(a.head.indices.size() % 3, 0u);
  for (std::uint32_t i : a.head.indices) ASSERT_LT(i, a.head.positions.size());
  for (const auto& p : a.head.positions) ASSERT_LT(std::abs(a.sdf->sample(p)), kDefaultHeadCell);
}

TEST(DefaultHead, ScalpRootsSitOnTheFieldAboveTheEars) {
  for (const auto& p : makeDefaultScalp().positions) {
    ASSERT_LT(std::abs(headDistance(p)), 1e-4f);
    // No root on the ears (they stand out at |x| > 0.07 around y = -0.02).
    EXPECT_FALSE(std::abs(p.x) > 0.062f && p.y < 0.0f && p.z > -0.04f) << p.x << " " << p.y << " " << p.z;
  }
}

TEST(DefaultHead, RestPoseHangsLikeHairOutsideTheColliders) {
  const auto& g = asset().guides;
  std::uint32_t hanging = 0;
  glm::vec3 meanTipDir(0.0f);
  for (std::uint32_t i = 0; i < g.guideCount(); ++i) {
    auto guide = g.guide(i);
    for (std::uint32_t k = 1; k < 7; ++k) EXPECT_LE(insideDepth(guide[k]), 1e-4f);
    glm::vec3 tipDir = glm::normalize(guide[6] - guide[5]);
    meanTipDir += tipDir;
    hanging += tipDir.y < -0.3f;
  }
  meanTipDir /= float(g.guideCount());
  EXPECT_LT(meanTipDir.y, -0.6f);          // tips point down on average
  EXPECT_GT(hanging, g.guideCount() * 9 / 10);  // not a hedgehog
  // Long hair: the lowest tips reach below the chin.
  float lowest = 0.0f;
  for (std::uint32_t i = 0; i < g.guideCount(); ++i) lowest = std::min(lowest, g.guide(i)[6].y);
  EXPECT_LT(lowest, -0.12f);
}

TEST(DefaultHead, NoStrandHangsOverTheFace) {
  const auto& g = asset().guides;
  for (std::uint32_t i = 0; i < g.guideCount(); ++i)
    for (std::uint32_t k = 1; k < 7; ++k) {
      glm::vec3 p = g.guide(i)[k];
      EXPECT_FALSE(p.z > 0.09f && std::abs(p.x) < 0.04f && p.y < 0.0f) << "guide " << i << " particle " << k;
    }
}

TEST(DefaultHead, TopologyAndDeterminism) {
  const auto& a = asset();
  EXPECT_EQ(a.topology.strands.size(), DensityOptions{}.totalStrands);
  HairAsset b = buildDefaultHeadAsset();
  EXPECT_EQ(a.guides.positions, b.guides.positions);
  EXPECT_EQ(a.topology.strands.back().barycentric, b.topology.strands.back().barycentric);
}
// Render strands are blends of their triangle's three guides and are not collided: where the guides of a
// triangle part to opposite sides of the head, the blend runs through the skull. Every triangle is probed at
// 64 points spread over it (the fold of an 8 x 8 grid), every particle but the root.
TEST(DefaultHead, NoStrandBlendedFromItsGuidesEntersTheHead) {
  const auto& a = asset();
  const auto& g = a.guides;
  std::uint32_t entering = 0;
  for (std::size_t t = 0; t < a.topology.triangles.size(); ++t) {
    const glm::uvec3 tri = a.topology.triangles[t];
    float deepest = 0.0f;
    for (std::uint32_t s = 0; s < 64; ++s) {
      const glm::vec3 b = foldBarycentric((s % 8 + 0.5f) / 8.0f, (s / 8 + 0.5f) / 8.0f);
      for (std::uint32_t k = 1; k < g.particlesPerGuide; ++k)
        deepest = std::max(deepest, insideDepth(b.x * g.guide(tri.x)[k] + b.y * g.guide(tri.y)[k] + b.z * g.guide(tri.z)[k]));
    }
    entering += deepest > 0.0f;
    EXPECT_LE(deepest, 0.0f) << "triangle " << t << ": a blended strand " << deepest << " m inside the head";
  }
  EXPECT_EQ(entering, 0u);
}
}  // namespace
}  // namespace hp
