// .hair models as assets: resampled guides, kept strands, fitted colliders, root topology.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/segment_profile.h"
#include "samples/tools/host/synthetic_hair.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
HairFileData model(std::uint32_t strands = 600, std::uint32_t pointsPerStrand = 30) {
  SyntheticHairOptions o;
  o.strands = strands;
  o.points = strands * pointsPerStrand;
  return makeSyntheticHair(o);
}

TEST(HairImport, SyntheticModelHasExactCountsAndVaryingStrands) {
  HairFileData d = model();
  EXPECT_NO_THROW(validateHairData(d, "synthetic"));
  EXPECT_EQ(d.pointCount(), 600u * 30u);
  EXPECT_NE(d.strandPointCount(0), d.strandPointCount(1));
}

TEST(HairImport, ResamplesEveryStrandKeepingRootsTipsAndLength) {
  HairFileData d = model();
  HairImportOptions o;
  GuideSet g = guidesFromHair(d, o, "m.hair");
  ASSERT_EQ(g.guideCount(), 600u);
  auto offsets = d.strandOffsets();
  for (std::uint32_t s = 0; s < 600; ++s) {
    std::span<const glm::vec3> in(d.points.data() + offsets[s], d.strandPointCount(s));
    EXPECT_EQ(g.guide(s)[0], in.front());
    EXPECT_EQ(g.guide(s)[6], in.back());
    // The synthetic strands are wavy; 7 particles cut across the waves (a smooth arc keeps 1%:
    // see Resample.KeepsRootTipAndArcLength).
    EXPECT_NEAR(polylineLength(g.guide(s)) / polylineLength(in), 1.0f, 0.1f);
  }
}

TEST(HairImport, KeepsStrandsAsTheyAreWhenAsked) {
  HairFileData d;
  d.strandCount = 2;
  d.defaultSegments = 2;
  d.points = {{0, 0, 0}, {0, -1, 0}, {0, -3, 0}, {1, 0, 0}, {1, -1, 0}, {1, -2, 0}};
  HairImportOptions o;
  o.keepStrands = true;
  o.transform.translation = glm::vec3(0, 10, 0);
  GuideSet g = guidesFromHair(d, o, "k.hair");
  EXPECT_EQ(g.particlesPerGuide, 3u);
  EXPECT_EQ(g.guide(0)[2], glm::vec3(0, 7, 0));
  HairFileData mixed = model(10, 5);
  EXPECT_ERROR_CONTAINS(guidesFromHair(mixed, o, "mixed.hair"),
                        "mixed.hair: keeping strands as they are needs one point count for all strands");
  HairFileData tooLong;
  tooLong.strandCount = 1;
  tooLong.defaultSegments = 69;
  tooLong.points.assign(70, glm::vec3(0.0f));
  EXPECT_ERROR_CONTAINS(guidesFromHair(tooLong, o, "long.hair"), "particles per guide must be in [2, 64], got 70");
}

TEST(HairImport, BuildsTopologyAndFitsAHeadCollider) {
  HairImportOptions o;
  o.density.totalStrands = 5000;
  HairAsset a = importHairAsset(model(), o, "m.hair");
  EXPECT_EQ(a.name, "m.hair");
  EXPECT_GT(a.topology.triangles.size(), 600u);  // about 2 per root on an open cap
  EXPECT_EQ(a.topology.strands.size(), 5000u);
  ASSERT_EQ(a.colliders.size(), 1u);
  EXPECT_NEAR(a.colliders[0].radius, 0.1f, 1e-4f);
  EXPECT_NEAR(glm::length(a.colliders[0].center), 0.0f, 1e-4f);
  // A fitted sphere collides but is not drawn: it would hide the hair it was fitted to.
  EXPECT_TRUE(a.fittedCollider);
  EXPECT_TRUE(a.head.positions.empty());
}

// On a scalp that is not a sphere (here a lumpy cap of an ellipsoid of semi-axes 10, 8 and 10 cm) the
// least-squares sphere runs through the roots; the fitted collider keeps its centre and shrinks to the nearest
// root, so no root starts inside it (the pearls next to such roots were pushed out on the first frames); one root
// far inside (at the centre here) shrinks it to half its size, no further.
TEST(HairImport, TheFittedColliderLiesUnderEveryRoot) {
  HairFileData d;
  d.strandCount = 400;
  d.defaultSegments = 3;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float a = 2.39996f * float(s), y = 1.0f - 0.7f * float(s) / float(d.strandCount), r = std::sqrt(1.0f - y * y);
    const float bump = 1.0f + 0.08f * std::sin(5.0f * a) * r;  // a lumpy scalp, +-8% at the sides
    const glm::vec3 root(0.1f * bump * r * std::cos(a), 0.08f * y, 0.1f * bump * r * std::sin(a));
    for (int k = 0; k < 4; ++k) d.points.push_back(root + glm::vec3(0.0f, -0.05f * float(k), 0.0f));
  }
  HairImportOptions o;
  o.density.totalStrands = 1000;
  const HairAsset a = importHairAsset(d, o, "oblate.hair");
  ASSERT_EQ(a.colliders.size(), 1u);
  const SphereCollider& c = a.colliders[0];
  float nearest = INFINITY, farthest = 0.0f;
  for (const glm::vec3& root : a.guides.roots()) {
    nearest = std::min(nearest, glm::distance(root, c.center));
    farthest = std::max(farthest, glm::distance(root, c.center));
  }
  EXPECT_FLOAT_EQ(c.radius, nearest);  // the nearest root lies on it, none inside
  EXPECT_GT(farthest - nearest, 0.01f) << "the roots are not all on one sphere: the fit alone would cut through them";
  EXPECT_GT(c.radius, 0.05f);
  // A root at the fitted centre: the sphere keeps half the fitted radius.
  HairFileData outlier = d;
  outlier.strandCount += 1;
  for (int k = 0; k < 4; ++k) outlier.points.push_back(c.center + glm::vec3(0.0f, -0.05f * float(k), 0.0f));
  const HairAsset b = importHairAsset(outlier, o, "outlier.hair");
  ASSERT_EQ(b.colliders.size(), 1u);
  const std::vector<glm::vec3> roots = b.guides.roots();
  EXPECT_FLOAT_EQ(b.colliders[0].radius, 0.5f * fitSphere(roots).sphere.radius);
}

TEST(HairImport, SceneCollidersReplaceTheFittedOne) {
  HairImportOptions o;
  o.colliders = std::vector<SphereCollider>{{{0, 0, 0}, 0.05f}, {{0, -0.2f, 0}, 0.04f}};
  HairAsset a = importHairAsset(model(), o, "m.hair");
  EXPECT_EQ(a.colliders, *o.colliders);
  EXPECT_FALSE(a.fittedCollider);  // given colliders are drawn as the head
  EXPECT_FALSE(a.head.positions.empty());
}

TEST(HairImport, RootsThatCannotBeTriangulatedAreAnError) {
  HairFileData d;
  d.strandCount = 3;
  d.defaultSegments = 1;
  d.points = {{0, 0, 0}, {0, -1, 0}, {1, 0, 0}, {1, -1, 0}, {2, 0, 0}, {2, -1, 0}};
  EXPECT_ERROR_CONTAINS(importHairAsset(d, {}, "line.hair"), "line.hair: cannot triangulate the strand roots");
}

// A scale or translation that takes the model past 10 km is refused by name before its distances overflow
// (a scale of 1e24 crashed the import: the fit and the parting margin met infinite distances).
TEST(HairImport, AModelPlacedBeyondTenKilometresIsRefused) {
  for (const float scale : {1e21f, 1e24f, 1e7f}) {
    HairImportOptions o;
    o.transform.scale = scale;
    EXPECT_ERROR_CONTAINS(importHairAsset(model(), o, "far.hair"), "far.hair: point 0 lies at");
  }
  HairImportOptions moved;
  moved.transform.translation = glm::vec3(0.0f, 2e4f, 0.0f);
  EXPECT_ERROR_CONTAINS(importHairAsset(model(), moved, "far.hair"), "check the scale and translation");
  std::vector<glm::vec3> inside = {glm::vec3(9999.0f), glm::vec3(-9999.0f)};
  EXPECT_NO_THROW(checkHeadSpaceExtent(inside, "near"));
}
}  // namespace
}  // namespace hp
