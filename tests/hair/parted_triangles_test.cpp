// Scalp triangles whose guides part around the head: dropped, so no render strand is blended through it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/parted_triangles.h"
#include "engine/core/hair/root_topology.h"
#include "engine/core/hair/scene.h"
#include "tests/hair/gltf_test_file.h"
#include "tests/hair/hair_test_util.h"
#include "tests/hair/parted_crown.h"

namespace hp {
namespace {
constexpr float kRadius = test::kPartedCrownRadius;
const SphereCollider kHead{glm::vec3(0.0f), kRadius};
using test::partedCrown;

// The triangles parted around the head's sphere, at the margin an import sizes from it.
PartedTriangles partedByTheHead(const GuideSet& g, std::span<const glm::uvec3> triangles) {
  return dropPartedTriangles(g, triangles, CollisionBody{std::span(&kHead, 1)}, kPartedMargin * kRadius);
}

std::vector<glm::uvec3> crownTriangles(const GuideSet& g) {
  return triangulateRoots(g.roots(), glm::vec3(0.0f)).triangles;
}

// Every strand's blend stays outside the head (past its root) at every particle.
void expectNoStrandThroughTheHead(const InterpolationTopology& topology, const GuideSet& g) {
  for (const StrandBinding& s : topology.strands) {
    const glm::uvec3 t = topology.triangles[s.triangle];
    for (std::uint32_t k = 1; k < g.particlesPerGuide; ++k) {
      const glm::vec3 p = s.barycentric.x * g.guide(t.x)[k] + s.barycentric.y * g.guide(t.y)[k] +
                          s.barycentric.z * g.guide(t.z)[k];
      ASSERT_GT(glm::length(p), 0.9f * kRadius) << "strand in triangle " << s.triangle << ", particle " << k;
    }
  }
}

// A UV sphere of `radius` at `centre` as an OBJ file.
void writeObjSphere(const std::filesystem::path& path, float radius, const glm::vec3& centre) {
  const test::GltfTestMesh m = test::uvSphere(radius, 64, 32);
  std::string obj;
  for (const glm::vec3& p : m.positions)
    obj += "v " + std::to_string(p.x + centre.x) + " " + std::to_string(p.y + centre.y) + " " + std::to_string(p.z + centre.z) + "\n";
  for (std::size_t i = 0; i < m.indices.size(); i += 3)
    obj += "f " + std::to_string(m.indices[i] + 1) + " " + std::to_string(m.indices[i + 1] + 1) + " " +
           std::to_string(m.indices[i + 2] + 1) + "\n";
  test::writeText(path, obj);
}

// The parted crown as a .hair file with a character mesh: the head sphere, faceted, `offset` from it.
Scene crownOnCharacter(const test::TempDir& dir, const glm::vec3& offset) {
  writeHairFile(dir / "crown.hair", test::hairFileOf(partedCrown(0.0f)));
  test::GltfTestMesh head = test::uvSphere(kRadius, 64, 32);
  for (glm::vec3& p : head.positions) p += offset;
  test::writeBytes(dir / "head.glb", test::glbBytes(head));
  Scene scene;
  scene.model.kind = ModelSpec::Kind::Hair;
  scene.model.path = dir / "crown.hair";
  scene.model.keepStrands = true;
  scene.mesh = CharacterMeshSpec{dir / "head.glb", 0.004f};
  return scene;
}

TEST(PartedTriangles, DropsTheTrianglesAcrossAPartingAndNoOther) {
  const GuideSet g = partedCrown(0.0f);
  const std::vector<glm::uvec3> triangles = crownTriangles(g);
  ASSERT_GT(triangles.size(), 100u);
  const PartedTriangles parted = partedByTheHead(g, triangles);
  std::uint32_t straddling = 0;
  for (const glm::uvec3& t : triangles) {
    const int right = int(g.root(t.x).x >= 0.0f) + int(g.root(t.y).x >= 0.0f) + int(g.root(t.z).x >= 0.0f);
    straddling += right == 1 || right == 2;
  }
  EXPECT_GT(straddling, 0u);
  EXPECT_EQ(parted.dropped, straddling);
  EXPECT_EQ(parted.kept.size() + parted.dropped, triangles.size());
  for (const glm::uvec3& t : parted.kept) {  // every kept triangle lies on one side, and its blends stay out
    const int right = int(g.root(t.x).x >= 0.0f) + int(g.root(t.y).x >= 0.0f) + int(g.root(t.z).x >= 0.0f);
    EXPECT_TRUE(right == 0 || right == 3);
    for (std::uint32_t k = 1; k < 7; ++k)
      EXPECT_GT(glm::length((g.guide(t.x)[k] + g.guide(t.y)[k] + g.guide(t.z)[k]) / 3.0f), 0.9f * kRadius);
  }
}

TEST(PartedTriangles, GuidesCombedOneWayKeepEveryTriangle) {
  const GuideSet g = partedCrown(-1.0f);  // every root right of the "parting": all combed toward +x
  const std::vector<glm::uvec3> triangles = crownTriangles(g);
  const PartedTriangles parted = partedByTheHead(g, triangles);
  EXPECT_EQ(parted.dropped, 0u);
  EXPECT_EQ(parted.kept, triangles);
}

TEST(PartedTriangles, WithoutCollidersOrWithAnUnknownGuideNothingIsDropped) {
  const GuideSet g = partedCrown(0.0f);
  const std::vector<glm::uvec3> triangles = crownTriangles(g);
  EXPECT_EQ(dropPartedTriangles(g, triangles, CollisionBody{}, kPartedMargin * kRadius).dropped, 0u);
  const std::vector<glm::uvec3> unknown = {glm::uvec3(0, 1, g.guideCount())};
  EXPECT_EQ(partedByTheHead(g, unknown).kept, unknown);
}

TEST(PartedTriangles, AnImportWhoseEveryTriangleIsPartedIsRefusedByName) {
  // One triangle over three corners of the patch, two left of the parting and one right of it: parted.
  const GuideSet g = partedCrown(0.0f);
  const std::vector<glm::uvec3> one = {glm::uvec3(0, 72, 8)};
  ASSERT_EQ(partedByTheHead(g, one).dropped, 1u);
  HairImportOptions o;
  o.colliders = std::vector<SphereCollider>{kHead};
  try {
    assembleImportedAsset(g, one, o, "parted.hair");
    ADD_FAILURE() << "an asset without a triangle to interpolate in was built";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("parted.hair: every one of its 1 root triangles"), std::string::npos) << e.what();
  }
}

TEST(PartedTriangles, AnImportedPartedModelInterpolatesNoStrandThroughItsHead) {
  const GuideSet g = partedCrown(0.0f);
  const HairFileData data = test::hairFileOf(g);
  HairImportOptions o;
  o.keepStrands = true;
  o.colliders = std::vector<SphereCollider>{kHead};
  const HairAsset asset = importHairAsset(data, o, "parted.hair");
  EXPECT_GT(asset.partedTriangles, 0u);
  expectNoStrandThroughTheHead(asset.topology, g);
}

TEST(PartedTriangles, ADistanceGridPartsTheSameTrianglesAsItsSphere) {
  const GuideSet g = partedCrown(0.0f);
  const std::vector<glm::uvec3> triangles = crownTriangles(g);
  const SdfGrid grid = sampleField([](const glm::vec3& p) { return glm::length(p) - kRadius; }, glm::vec3(-0.15f),
                                   glm::vec3(0.15f), 0.005f);
  const PartedTriangles bySphere = partedByTheHead(g, triangles);
  const PartedTriangles byGrid = dropPartedTriangles(g, triangles, CollisionBody{{}, &grid}, kPartedMargin * kRadius);
  EXPECT_GT(byGrid.dropped, 0u);
  EXPECT_EQ(byGrid.kept, bySphere.kept);
}

// A model drawing its own strands blends nothing, yet its parted triangles are dropped all the same: a density
// chosen later (Asset::withDensity rebuilds the topology over the asset's triangles) blends over them.
TEST(PartedTriangles, AModelDrawingItsOwnStrandsKeepsNoPartedTriangleForALaterDensity) {
  const GuideSet g = partedCrown(0.0f);
  HairImportOptions o;
  o.keepStrands = true;
  o.colliders = std::vector<SphereCollider>{kHead};
  o.density.mode = DensityOptions::Mode::Guides;
  const HairAsset own = importHairAsset(test::hairFileOf(g), o, "parted.hair");
  EXPECT_EQ(own.partedTriangles, partedByTheHead(g, crownTriangles(g)).dropped);
  ASSERT_EQ(own.topology.strands.size(), g.guideCount());  // every guide drawn, in its own place
  for (const StrandBinding& s : own.topology.strands)
    EXPECT_TRUE(s.barycentric.x == 1.0f || s.barycentric.y == 1.0f || s.barycentric.z == 1.0f) << s.triangle;
  DensityOptions later;
  later.totalStrands = 4000;
  expectNoStrandThroughTheHead(buildInterpolationTopology(g.roots(), own.topology.triangles, later), g);
}

// A character mesh that collides takes the place of the sphere fitted under the roots, in the parting test too:
// on the head, the same triangles are parted as by the head's sphere; a metre away from the hair, none is
// (the hair never meets it), though the sphere under the roots would part them.
TEST(PartedTriangles, ACharacterMeshIsTheBodyTheGuidesPartAround) {
  const test::TempDir dir;
  const GuideSet g = partedCrown(0.0f);
  const std::uint32_t bySphere = partedByTheHead(g, crownTriangles(g)).dropped;
  const HairAsset onHead = buildSceneAsset(crownOnCharacter(dir, glm::vec3(0.0f)));
  ASSERT_TRUE(onHead.characterCollides);
  EXPECT_GT(onHead.partedTriangles, 0u);
  EXPECT_EQ(onHead.partedTriangles, bySphere);
  const HairAsset away = buildSceneAsset(crownOnCharacter(dir, glm::vec3(1.0f, 0.0f, 0.0f)));
  ASSERT_TRUE(away.characterCollides);
  EXPECT_EQ(away.partedTriangles, 0u);
  Scene noMesh = crownOnCharacter(dir, glm::vec3(0.0f));
  noMesh.mesh.reset();
  EXPECT_GT(buildSceneAsset(noMesh).partedTriangles, 0u);  // the sphere under the roots parts them
}

// Scene collider meshes join the scene's spheres in the parting test: a sphere a metre away parts nothing, the
// head's mesh beside it parts what the head's sphere parts.
TEST(PartedTriangles, SceneColliderMeshesJoinTheirSpheres) {
  const test::TempDir dir;
  Scene scene = crownOnCharacter(dir, glm::vec3(0.0f));
  scene.mesh.reset();
  scene.colliders = std::vector<SphereCollider>{{glm::vec3(1.0f, 0.0f, 0.0f), 0.05f}};
  EXPECT_EQ(buildSceneAsset(scene).partedTriangles, 0u);
  writeObjSphere(dir / "head.obj", kRadius, glm::vec3(0.0f));
  scene.colliderMeshes = {MeshColliderSpec{dir / "head.obj", 0.004f}};
  const GuideSet g = partedCrown(0.0f);
  EXPECT_EQ(buildSceneAsset(scene).partedTriangles, partedByTheHead(g, crownTriangles(g)).dropped);
}

// Guides grown on an OBJ scalp part around a character mesh where it collides: the 49-guide cap's pole (9 of its
// triangles parted around the sphere fitted to the scalp) parts around a ball under the scalp, not around one
// far from it.
TEST(PartedTriangles, AnObjScalpOnACharacterMeshPartsAroundTheMesh) {
  const test::TempDir dir;
  Scene scene;
  scene.model.kind = ModelSpec::Kind::Obj;
  scene.model.path = std::filesystem::path(HAIRPIPE_TEST_DATA_DIR) / "scalp_cap.obj";
  scene.growth.length = 1.0f;
  EXPECT_EQ(buildSceneAsset(scene).partedTriangles, 9u);
  for (const float away : {0.0f, 4.0f}) {
    test::writeBytes(dir / "ball.glb", test::glbBytes(test::uvSphere(0.99f, 64, 32)));
    if (away > 0.0f) {
      test::GltfTestMesh far = test::uvSphere(0.99f, 64, 32);
      for (glm::vec3& p : far.positions) p.x += away;
      test::writeBytes(dir / "ball.glb", test::glbBytes(far));
    }
    scene.mesh = CharacterMeshSpec{dir / "ball.glb", 0.03f};
    const HairAsset asset = buildSceneAsset(scene);
    ASSERT_TRUE(asset.characterCollides);
    if (away > 0.0f) EXPECT_EQ(asset.partedTriangles, 0u) << "a ball " << away << " away";
    else EXPECT_GT(asset.partedTriangles, 0u);
  }
}

// With spheres only, the margin is a tenth of the sphere the roots lie on: an ear's small sphere or a torso's
// large one beside the head changes nothing (a torso ten times the head's size made it ten times wider).
TEST(PartedTriangles, TheMarginIsTheHeadsNotAnEarsOrATorsos) {
  const GuideSet g = partedCrown(0.0f);
  const std::uint32_t byHead = partedByTheHead(g, crownTriangles(g)).dropped;
  ASSERT_GT(byHead, 0u);
  HairImportOptions o;
  o.keepStrands = true;
  o.colliders = std::vector<SphereCollider>{
      kHead, {glm::vec3(0.11f, 0.0f, 0.0f), 0.01f}, {glm::vec3(0.0f, -1.2f, 0.0f), 1.0f}};
  EXPECT_EQ(importHairAsset(test::hairFileOf(g), o, "parted.hair").partedTriangles, byHead);
}
}  // namespace
}  // namespace hp
