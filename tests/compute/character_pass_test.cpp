// The skinned character on the device (compute/strands/character_pass.h, docs/THEORY.md §8.7): posed
// vertices match the CPU's linear blend skinning, and the distance grid rebuilt from the posed triangles
// matches the CPU's exact distances (sign included) within its band; beyond it the grid holds the band's
// value on the side the node is on (inside the body: minus).
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "compute/strands/character_pass.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/character_clip.h"
#include "samples/tools/host/sim_stats.h"
#include "samples/tools/simulation_driver.h"
#include "tests/hair/hair_test_util.h"
#include "engine/core/hair/gltf_mesh.h"
#include "engine/core/hair/sdf_mesh.h"
#include "engine/core/hair/skeleton_pose.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/sdf.h"
#include "tests/hair/gltf_test_file.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
// A 9 cm sphere whose upper part follows a "head" joint 5 cm up, turned 25 degrees about x, blended over the
// middle 12 cm (a sharper blend or a larger turn folds the skinned surface into itself, where no sign holds).
struct PosedSphere {
  CharacterMesh mesh;
  std::vector<glm::mat4> skin;
};

PosedSphere posedSphere() {
  test::GltfTestMesh m = test::uvSphere(0.09f, 24, 12);
  m.joints = {{"neck", -1, glm::vec3(0.0f)}, {"head", 0, glm::vec3(0.0f, 0.05f, 0.0f)}};
  for (const glm::vec3& p : m.positions) {
    const float w = glm::clamp((p.y + 0.06f) / 0.12f, 0.0f, 1.0f);
    m.vertexJoints.emplace_back(0, 1, 0, 0);
    m.vertexWeights.emplace_back(1.0f - w, w, 0.0f, 0.0f);
  }
  PosedSphere s{parseGltf(test::glbBytes(m), "sphere.glb", {}), {}};
  std::vector<JointPose> pose = restPose(s.mesh);
  pose[1].rotation = glm::angleAxis(glm::radians(25.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  s.skin = skinningMatrices(s.mesh, pose);
  return s;
}
}  // namespace

namespace {
// A closed 8 cm box of 12 triangles (shared corners: smooth normals), one joint at rest: sharp edges and corners.
// `m` (positions and triangles) bound wholly to one joint, at rest.
PosedSphere restingRigid(CharacterMesh m) {
  m.joints.assign(m.positions.size(), glm::uvec4(0));
  m.weights.assign(m.positions.size(), glm::vec4(1, 0, 0, 0));
  m.skeleton.push_back(Joint{"root"});
  finishCharacterMesh(m);
  return {std::move(m), {glm::mat4(1.0f)}};
}

PosedSphere restingBox() {
  CharacterMesh m;
  m.source = "box";
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1 ? 0.04f : -0.04f, i & 2 ? 0.04f : -0.04f, i & 4 ? 0.04f : -0.04f);
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) m.triangles.insert(m.triangles.end(), {{q[0], q[1], q[2]}, {q[0], q[2], q[3]}});
  return restingRigid(std::move(m));
}

// A regular tetrahedron of 8 cm edges (dihedral angles of 70.5 degrees: sharper than a face normal can judge).
PosedSphere restingTetrahedron() {
  CharacterMesh m;
  m.source = "tetrahedron";
  const float a = 0.04f / std::sqrt(2.0f);
  m.positions = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
  return restingRigid(std::move(m));
}

// Poses `s` on the device and compares with the CPU: posed vertices and normals, and at every grid node the
// distance to the posed triangles (brute force) within the band, the side where the CPU's ray-parity grid is
// sure of it (more than a cell from the surface), and the band's value on the right side beyond it.
void expectDeviceMatchesCpu(const vk::Context& ctx, const PosedSphere& s, float cell) {
  auto grid = std::make_shared<const SdfGrid>(meshSdf(s.mesh.positions, s.mesh.triangles, cell, 8));
  const SdfBuffer sdf(ctx, grid);
  CharacterPass pass(ctx, s.mesh, {}, sdf, nullptr);
  pass.setPose(s.skin);
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) { EXPECT_TRUE(pass.record(cmd)); }, "character");
  EXPECT_FALSE(pass.posePending());
  const SkinnedVertices cpu = skinMesh(s.mesh, s.skin);
  const auto posed = vk::readback<glm::vec4>(ctx, pass.posedPositions(), vk::BufferUse::TransferSrc, pass.vertexCount());
  const auto normals = vk::readback<glm::vec4>(ctx, pass.posedNormals(), vk::BufferUse::TransferSrc, pass.vertexCount());
  double worstPosition = 0.0, worstNormal = 0.0;
  for (std::size_t v = 0; v < cpu.positions.size(); ++v) {
    worstPosition = std::max(worstPosition, double(glm::distance(glm::vec3(posed[v]), cpu.positions[v])));
    worstNormal = std::max(worstNormal, double(glm::distance(glm::vec3(normals[v]), cpu.normals[v])));
  }
  EXPECT_LT(worstPosition, 1e-6);
  EXPECT_LT(worstNormal, 1e-5);
  const SdfGrid parity = meshSdf(cpu.positions, s.mesh.triangles, cell, 8);
  const std::size_t header = sizeof(gpu::SdfHeader) / sizeof(float);
  const auto values = vk::readback<float>(ctx, sdf.buffer(), vk::BufferUse::ComputeRead, header + grid->values.size());
  const float band = float(gpu::CHARACTER_SDF_BAND_CELLS) * cell;
  std::size_t inBand = 0, wrongSign = 0, beyondBand = 0, insideBeyond = 0;
  double worst = 0.0;
  for (std::uint32_t k = 0; k < grid->dims.z; ++k)
    for (std::uint32_t j = 0; j < grid->dims.y; ++j)
      for (std::uint32_t i = 0; i < grid->dims.x; ++i) {
        const glm::vec3 p = grid->node(i, j, k);
        const float device = values[header + grid->index(i, j, k)];
        float truth = 1e30f;
        for (const glm::uvec3& t : s.mesh.triangles)
          truth = std::min(truth, pointTriangleDistance(p, cpu.positions[t.x], cpu.positions[t.y], cpu.positions[t.z]));
        const float side = parity.sample(p);
        if (truth < 0.99f * band) {
          ++inBand;
          worst = std::max(worst, double(std::abs(std::abs(device) - truth)));
          if (std::abs(side) > cell && (device < 0.0f) != (side < 0.0f)) ++wrongSign;
        } else if (truth > 1.01f * band) {
          EXPECT_FLOAT_EQ(device, side < 0.0f ? -band : band) << i << " " << j << " " << k;
          ++beyondBand;
          insideBeyond += side < 0.0f ? 1u : 0u;
        }
      }
  std::cout << s.mesh.source << ": " << inBand << " nodes in the band: worst |distance| error " << worst << " m, "
            << wrongSign << " signs differ; " << insideBeyond << " of " << beyondBand << " beyond it inside\n";
  EXPECT_GT(inBand, 1000u);
  EXPECT_LT(worst, 1e-5);
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_GT(insideBeyond, 100u);  // the body's interior past the band
  EXPECT_GT(beyondBand - insideBeyond, 1000u);
}
}  // namespace

TEST_F(VulkanTest, ACharacterPosedOnTheDeviceMatchesTheCpu) {
  expectDeviceMatchesCpu(*ctx, posedSphere(), 0.18f / 48.0f);
  expectDeviceMatchesCpu(*ctx, restingBox(), 0.08f / 40.0f);  // right-angled edges and corners
  expectDeviceMatchesCpu(*ctx, restingTetrahedron(), 0.06f / 40.0f);  // sharper ones
}

namespace {
// 200 guides of 7 particles hanging 10 cm from the crown of a 9 cm sphere (.hair), on the sphere skinned to a
// "head" joint 5 cm up (weights blended over the middle 12 cm) whose clip "nod" turns it 45 degrees about x
// and back each second; a 4 mm distance grid.
HairAsset noddingCharacter(const test::TempDir& dir) {
  HairFileData hair;
  hair.strandCount = 200;
  hair.defaultSegments = 6;
  for (std::uint32_t s = 0; s < hair.strandCount; ++s) {
    const float a = 0.61f * float(s), up = 0.15f + 0.8f * float(s) / 199.0f;
    const glm::vec3 n = glm::normalize(glm::vec3(std::sin(a) * up, 1.0f, std::cos(a) * up));
    for (int k = 0; k < 7; ++k) hair.points.push_back(0.0905f * n + 0.017f * float(k) * glm::normalize(0.6f * n + glm::vec3(0, -1, 0)));
  }
  writeHairFile(dir / "crown.hair", hair);
  test::GltfTestMesh m = test::uvSphere(0.09f);
  m.joints = {{"neck", -1, glm::vec3(0.0f)}, {"head", 0, glm::vec3(0.0f, 0.05f, 0.0f)}};
  for (const glm::vec3& p : m.positions) {
    const float w = glm::clamp((p.y + 0.06f) / 0.12f, 0.0f, 1.0f);
    m.vertexJoints.emplace_back(0, 1, 0, 0);
    m.vertexWeights.emplace_back(1.0f - w, w, 0.0f, 0.0f);
  }
  const glm::quat turned = glm::angleAxis(glm::radians(45.0f), glm::vec3(1, 0, 0));
  m.clips.push_back({"nod", 1, {0.0f, 0.5f, 1.0f}, {glm::quat(1, 0, 0, 0), turned, glm::quat(1, 0, 0, 0)}});
  test::writeBytes(dir / "head.glb", test::glbBytes(m));
  Scene scene;
  scene.model.kind = ModelSpec::Kind::Hair;
  scene.model.path = dir / "crown.hair";
  scene.mesh = CharacterMeshSpec{dir / "head.glb", 0.004f};
  return buildSceneAsset(scene);
}
}  // namespace

// Through 300 frames of the clip (five nods), read back every 10th frame: no particle's centre is inside the
// posed mesh, and every free particle keeps at least half its pearl radius from it, measured exactly against
// the CPU's skinning of the same pose. Without the device's rebuilt grid (the rest pose's kept), the nod
// drives the head into the hair: a negative control that must fail the same bound.
TEST_F(VulkanTest, HairOverASkinnedMeshStaysOutsideThroughItsAnimation) {
  const test::TempDir dir;
  const HairAsset asset = noddingCharacter(dir);
  ASSERT_TRUE(asset.characterCollides);
  double worst[2] = {1e30, 1e30};
  for (const bool rebuild : {true, false}) {
    SimulationParams params;
    SimulatePass pass(*ctx, asset, params, glm::mat4(1.0f), nullptr, characterScalp(asset));
    SimulationDriver driver(*ctx, pass, HeadAnimation::None, 0.09f, SimulationDriver::Timing::None);
    CharacterClip clip = characterClip(asset, "nod");
    clip.posesMesh = rebuild;
    driver.setCharacterClip(clip);
    for (int chunk = 0; chunk < 30; ++chunk) {
      driver.runFrames(10);
      const std::vector<glm::vec4> positions = driver.readPositions();
      const MeshPenetration pen = meshPenetration(positions, pass.particlesPerGuide(), driver.characterVertices(),
                                                  asset.character->triangles, glm::mat4(1.0f));
      worst[rebuild ? 0 : 1] = std::min(worst[rebuild ? 0 : 1], pen.minClearance);
    }
  }
  std::cout << "smallest clearance from the posed mesh over 300 frames: " << worst[0] << " m (rest grid kept: " << worst[1] << " m)\n";
  EXPECT_GT(worst[0], 0.5 * SimulationParams{}.pearlRadius);
  EXPECT_LT(worst[1], 0.5 * SimulationParams{}.pearlRadius);  // the control fails the bound
}
