// Distance grids built from triangle meshes: exact distances (against analytic shapes), the sign
// from ray parity, refusals, and the scene's "colliders": [{"mesh": ...}].
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "engine/core/hair/sdf_mesh.h"

namespace hp {
namespace {
// A closed axis-aligned box of half size h, 12 triangles, counter-clockwise from outside.
void boxMesh(float h, std::vector<glm::vec3>& pos, std::vector<glm::uvec3>& tris) {
  for (int i = 0; i < 8; ++i) pos.emplace_back(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h);
  tris = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
          {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
}

float boxDistance(const glm::vec3& p, float h) {
  const glm::vec3 q = glm::abs(p) - glm::vec3(h);
  return glm::length(glm::max(q, glm::vec3(0.0f))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0f);
}

std::vector<glm::uvec3> triangles(const HeadMesh& m) {
  std::vector<glm::uvec3> t;
  for (std::size_t i = 0; i < m.indices.size(); i += 3) t.emplace_back(m.indices[i], m.indices[i + 1], m.indices[i + 2]);
  return t;
}
}  // namespace

TEST(SdfMesh, BoxGridIsTheBoxDistanceAtEveryNode) {
  std::vector<glm::vec3> pos;
  std::vector<glm::uvec3> tris;
  boxMesh(0.1f, pos, tris);
  const SdfGrid g = meshSdf(pos, tris, 0.01f);
  float worst = 0.0f;
  for (std::uint32_t k = 0; k < g.dims.z; ++k)
    for (std::uint32_t j = 0; j < g.dims.y; ++j)
      for (std::uint32_t i = 0; i < g.dims.x; ++i)
        worst = std::max(worst, std::abs(g.at(i, j, k) - boxDistance(g.node(i, j, k), 0.1f)));
  EXPECT_LT(worst, 1e-5f);
  EXPECT_LT(g.sample(glm::vec3(0.0f)), -0.09f);
}

TEST(SdfMesh, SphereMeshGridIsCloseToTheSphereDistance) {
  const HeadMesh sphere = makeEllipsoidMesh(glm::vec3(0.02f, -0.01f, 0.0f), glm::vec3(0.1f), 64, 32);
  const SdfGrid g = meshSdf(sphere.positions, triangles(sphere), 0.005f);
  float worst = 0.0f;
  std::size_t wrongSign = 0;
  for (std::uint32_t k = 0; k < g.dims.z; ++k)
    for (std::uint32_t j = 0; j < g.dims.y; ++j)
      for (std::uint32_t i = 0; i < g.dims.x; ++i) {
        const float exact = glm::length(g.node(i, j, k) - glm::vec3(0.02f, -0.01f, 0.0f)) - 0.1f;
        worst = std::max(worst, std::abs(g.at(i, j, k) - exact));
        wrongSign += std::abs(exact) > 0.002f && (exact < 0.0f) != (g.at(i, j, k) < 0.0f);
      }
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_LT(worst, 0.0015f);  // the faceted mesh sits up to ~1.2 mm inside the sphere at this tessellation
}

TEST(SdfMesh, BadMeshesAreRefused) {
  std::vector<glm::vec3> pos{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(meshSdf(pos, std::vector<glm::uvec3>{}), Error);
  EXPECT_THROW(meshSdf(pos, std::vector<glm::uvec3>{{0, 1, 5}}), Error);
  std::vector<glm::vec3> nan{{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
  EXPECT_THROW(meshSdf(nan, std::vector<glm::uvec3>{{0, 1, 2}}), Error);
  EXPECT_THROW(meshSdf(pos, std::vector<glm::uvec3>{{0, 1, 2}}, 1e-5f), Error);  // too many nodes
  // Forty triangles each across the whole unit cube at a cell of 1/190: the grid (7.8M nodes) fits, their near
  // band (~290M distance tests, minutes) does not, and is refused before any test is made.
  const std::vector<glm::vec3> corners{{0, 0, 0}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  std::vector<glm::uvec3> spanning;
  for (std::uint32_t t = 0; t < 40; ++t) spanning.push_back(t % 2 ? glm::uvec3(0, 1, 2) : glm::uvec3(1, 2, 3));
  try {
    meshSdf(corners, spanning, 1.0f / 190.0f);
    ADD_FAILURE() << "the near band's cost was not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("collider mesh: 40 triangles at a cell of 0.00526316 need"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("more than the 250000000 allowed"), std::string::npos) << e.what();
  }
}

TEST(SdfMesh, SceneMeshColliderReplacesTheHeadField) {
  const auto dir = std::filesystem::temp_directory_path() / "hairpipe_sdf_mesh_scene";
  std::filesystem::create_directories(dir);
  std::vector<glm::vec3> pos;
  std::vector<glm::uvec3> tris;
  boxMesh(0.12f, pos, tris);
  {
    std::ofstream obj(dir / "body.obj");
    for (const auto& p : pos) obj << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const auto& t : tris) obj << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
  }
  const Scene s = parseScene(R"({"colliders": [{"mesh": "body.obj", "cell": 0.01}, {"center": [0, 1, 0], "radius": 0.05}]})",
                             "scene.json", dir);
  ASSERT_EQ(s.colliderMeshes.size(), 1u);
  EXPECT_EQ(s.colliderMeshes[0].path, dir / "body.obj");
  const HairAsset a = buildSceneAsset(s);
  ASSERT_TRUE(a.sdf);
  EXPECT_EQ(a.colliders.size(), 1u);
  EXPECT_NEAR(a.sdf->sample(glm::vec3(0.0f)), -0.12f, 1e-4f);
  EXPECT_NEAR(a.sdf->sample(glm::vec3(0.2f, 0.0f, 0.0f)), 0.08f, 1e-4f);
  // Spheres alone drop the head's field; a missing mesh or a bad cell names the path.
  EXPECT_FALSE(buildSceneAsset(parseScene(R"({"colliders": [{"center": [0, 0, 0], "radius": 0.1}]})", "s", dir)).sdf);
  EXPECT_THROW(buildSceneAsset(parseScene(R"({"colliders": [{"mesh": "missing.obj"}]})", "s", dir)), Error);
  try {
    parseScene(R"({"colliders": [{"mesh": "body.obj", "cell": -1}]})", "s.json", dir);
    ADD_FAILURE() << "a negative cell was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/colliders/0/cell"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}
}  // namespace hp
