// The skin's transfer (engine/core/hair/skin_transfer.h) on shapes whose light is known in closed form, and
// on the default head where the jaw shades the neck.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/skin_transfer.h"
#include "engine/core/hair/triangle_bvh.h"
#include "engine/core/shading/environment_sh.h"
#include "shaders/shared/environment.h"

using namespace hp;

namespace {
constexpr float kPi = 3.14159265358979f;

// A square of side `size` centred at `centre` in the plane spanned by u and v (unit), facing u x v,
// split into n x n cells.
void addSquare(HeadMesh& mesh, const glm::vec3& centre, const glm::vec3& u, const glm::vec3& v, float size, int n) {
  const std::uint32_t first = static_cast<std::uint32_t>(mesh.positions.size());
  const glm::vec3 normal = glm::normalize(glm::cross(u, v));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      mesh.positions.push_back(centre + size * ((float(i) / n - 0.5f) * u + (float(j) / n - 0.5f) * v));
      mesh.normals.push_back(normal);
    }
  auto at = [&](int i, int j) { return first + std::uint32_t(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
}

// The clamped cosine about n in the SH basis: A_l Y_i(n) (A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4).
float cosineLobe(std::uint32_t i, const glm::vec3& n) {
  const float band = i == 0 ? kPi : i < 4 ? 2.0f * kPi / 3.0f : kPi / 4.0f;
  return band * gpu::envShBasis(i, n);
}

// Irradiance from a radiance SH `light` through transfer coefficients.
float irradiance(const std::array<float, 9>& transfer, const std::array<float, 9>& light) {
  float e = 0.0f;
  for (std::size_t i = 0; i < 9; ++i) e += transfer[i] * light[i];
  return e;
}

// A uniform sky of radiance 1 in the SH basis.
std::array<float, 9> uniformSky() { return {2.0f * std::sqrt(kPi), 0, 0, 0, 0, 0, 0, 0, 0}; }
}  // namespace

TEST(TriangleBvh, FindsTheNearestTriangleAndItsFace) {
  HeadMesh mesh;
  addSquare(mesh, {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, 2.0f, 4);  // facing +y
  addSquare(mesh, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, 2.0f, 4);  // facing +y, above
  const TriangleBvh bvh(mesh.positions, mesh.indices);
  const auto down = bvh.closestHit({0.1f, 2.0f, 0.2f}, {0, -1, 0}, 0.0f, INFINITY);
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->t, 1.0f, 1e-5f);
  EXPECT_TRUE(down->front);
  EXPECT_GE(down->triangle, 32u) << "the upper square's triangles come second";
  const auto up = bvh.closestHit({0.1f, 0.5f, 0.2f}, {0, 1, 0}, 0.0f, INFINITY);
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->t, 0.5f, 1e-5f);
  EXPECT_FALSE(up->front) << "from below the upper square shows its back";
  EXPECT_FALSE(bvh.closestHit({0.1f, 0.5f, 0.2f}, {0, 1, 0}, 0.0f, 0.4f)) << "tMax stops short of it";
  EXPECT_FALSE(bvh.closestHit({3.0f, 0.5f, 0.0f}, {0, 1, 0}, 0.0f, INFINITY)) << "beside both";
  EXPECT_THROW(TriangleBvh(mesh.positions, std::vector<std::uint32_t>{0, 1, 999}), Error);
}

TEST(SkinTransfer, AnOpenPlaneSeesTheWholeSkyThroughItsCosineLobe) {
  HeadMesh mesh;
  addSquare(mesh, {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, 1.0f, 8);
  const SkinTransfer t = computeSkinTransfer(mesh);
  ASSERT_EQ(t.direct.size(), mesh.positions.size());
  const glm::vec3 up(0, 1, 0);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_EQ(t.blocked[v], 0.0f);
    EXPECT_EQ(t.reflecting[v], 0.0f);
    // Nothing in the way: no ray is blocked, so the lobe is exact (the estimator for open vertices).
    for (std::uint32_t i = 0; i < 9; ++i) {
      EXPECT_EQ(t.occluded[v][i], 0.0f);
      EXPECT_NEAR(t.direct[v][i], cosineLobe(i, up), 1e-6f) << "vertex " << v << " i " << i;
    }
    for (float b : t.bounce[v]) EXPECT_EQ(b, 0.0f);
  }
  // Under a uniform sky of radiance 1 the plane receives pi.
  EXPECT_NEAR(irradiance(t.direct[40], uniformSky()), kPi, 0.02f);
}

TEST(SkinTransfer, APatchAboveALitFloorReceivesTheFloorsLightOnce) {
  HeadMesh mesh;
  addSquare(mesh, {0, 0, 0}, {1, 0, 0}, {0, 0, -1}, 200.0f, 2);   // the floor, facing up
  addSquare(mesh, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, 0.2f, 2);      // a small patch at height 1, facing down
  const SkinTransfer t = computeSkinTransfer(mesh);
  const std::size_t patch = 9 + 4;  // the patch's centre vertex
  ASSERT_NEAR(mesh.normals[patch].y, -1.0f, 1e-6f);
  // The floor covers all but sin^2 of the half-angle of its edge, 1/(1 + 100^2), of the patch's view.
  EXPECT_NEAR(t.blocked[patch], 1.0f, 1e-3f);
  EXPECT_NEAR(irradiance(t.direct[patch], uniformSky()), 0.0f, 0.01f) << "the patch sees no sky";
  // The floor sees the sky (pi under radiance 1) and passes it on: per unit albedo the patch receives pi.
  EXPECT_NEAR(irradiance(t.bounce[patch], uniformSky()), kPi, 0.05f);
  // A sun straight above, of irradiance 1 (radiance SH of a direction: Y_i(l)): the floor receives what its
  // order-2 lobe gives at its peak, sum_l A_l (2l + 1) / (4 pi) = 1.0625, and the patch as much by bounce.
  std::array<float, 9> sun{};
  for (std::uint32_t i = 0; i < 9; ++i) sun[i] = gpu::envShBasis(i, glm::vec3(0, 1, 0));
  EXPECT_NEAR(irradiance(t.bounce[patch], sun), irradiance(t.direct[4], sun), 0.02f);
  EXPECT_NEAR(irradiance(t.direct[4], sun), 1.0625f, 0.05f);
}

// A vertex on a floor beside walls that rise from it (smoothing off, 256 rays) against the closed forms: one
// wall hides the half of the hemisphere on its side (x < 0), and of the lobe about +y it leaves
//   direct_0 = Y_0 pi / 2,  direct_1 (y) = 0.4886 pi / 3,  direct_3 (x) = 0.4886 x 2/3,  direct_2 (z) = 0
// (the integrals of Y_i cos over the half-hemisphere x > 0); two walls (x < 0 and z < 0) leave the quarter
// x > 0, z > 0: Y_0 pi / 4, 0.4886 pi / 6, 0.4886 / 3 for x and for z. Half blocked takes the estimator for
// mostly open vertices, three quarters the one for mostly blocked ones; a wrong ray distribution (the radius
// of Malley's disc, the basis about n) moves these by far more than the tolerance.
TEST(SkinTransfer, WallsBesideAFloorHideTheirShareOfTheLobe) {
  const float y0 = 0.2820948f, y1 = 0.4886025f;
  auto floorAt = [](HeadMesh& mesh) {
    mesh.positions.push_back({0.001f, 0.0f, 0.001f});  // the vertex, just off the walls
    mesh.normals.push_back({0.0f, 1.0f, 0.0f});
  };
  HeadMesh oneWall;
  floorAt(oneWall);
  addSquare(oneWall, {0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 400.0f, 1);  // the plane x = 0, facing +x
  const SkinTransfer a = computeSkinTransfer(oneWall, {256, 0});
  EXPECT_NEAR(a.blocked[0], 0.5f, 0.01f);
  EXPECT_NEAR(a.reflecting[0], 0.5f, 0.01f);
  EXPECT_NEAR(a.direct[0][0], y0 * kPi / 2.0f, 0.01f);
  EXPECT_NEAR(a.direct[0][1], y1 * kPi / 3.0f, 0.01f);
  EXPECT_NEAR(a.direct[0][2], 0.0f, 0.01f);
  EXPECT_NEAR(a.direct[0][3], y1 * 2.0f / 3.0f, 0.01f);
  HeadMesh twoWalls = oneWall;
  addSquare(twoWalls, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 400.0f, 1);  // the plane z = 0, facing +z
  const SkinTransfer b = computeSkinTransfer(twoWalls, {256, 0});
  EXPECT_NEAR(b.blocked[0], 0.75f, 0.01f);
  EXPECT_NEAR(b.direct[0][0], y0 * kPi / 4.0f, 0.01f);
  EXPECT_NEAR(b.direct[0][1], y1 * kPi / 6.0f, 0.01f);
  EXPECT_NEAR(b.direct[0][2], y1 / 3.0f, 0.01f);
  EXPECT_NEAR(b.direct[0][3], y1 / 3.0f, 0.01f);
  // Turning the walls' faces away: they still block, but pass nothing on.
  HeadMesh backs = twoWalls;
  for (std::size_t k = 0; k + 2 < backs.indices.size(); k += 3) std::swap(backs.indices[k + 1], backs.indices[k + 2]);
  const SkinTransfer c = computeSkinTransfer(backs, {256, 0});
  EXPECT_NEAR(c.blocked[0], 0.75f, 0.01f);
  EXPECT_EQ(c.reflecting[0], 0.0f);
  for (float v : c.bounce[0]) EXPECT_EQ(v, 0.0f);
}

// The transfer turns with the mesh: a strip of a cylinder (axis y, normals from -60 to +60 degrees about +x)
// under an overhanging ceiling, and the same turned a quarter about y (normals about +z). What a vertex hides is
// smoothed in tangent frames that, for the first mesh, turn half a turn where the normals cross n.z = 0; the
// neighbours' coefficients must be carried across (without it the ceiling's side, the m = +-1 terms, cancelled
// there). Measured: within 0.007 of the turned mesh's coefficients (256 rays), 0.35 when the twist is left out.
TEST(SkinTransfer, WhatAVertexHidesTurnsWithTheMesh) {
  HeadMesh strip;
  const int around = 16, up = 4;
  for (int j = 0; j <= up; ++j)
    for (int i = 0; i <= around; ++i) {
      const float a = glm::radians(-60.0f + 120.0f * float(i) / around);
      const glm::vec3 n(std::cos(a), 0.0f, std::sin(a));
      strip.positions.push_back(n + glm::vec3(0.0f, 0.5f * float(j) / up - 0.25f, 0.0f));
      strip.normals.push_back(n);
    }
  for (int j = 0; j < up; ++j)
    for (int i = 0; i < around; ++i) {
      const std::uint32_t a = j * (around + 1) + i, b = a + 1, c = a + around + 1, d = c + 1;
      strip.indices.insert(strip.indices.end(), {a, c, b, b, c, d});
    }
  addSquare(strip, {1.3f, 0.35f, 0.0f}, {1, 0, 0}, {0, 0, 1}, 1.2f, 2);  // the ceiling over the strip's outside, facing down
  // The strip's triangles face outward.
  const glm::vec3 e1 = strip.positions[1] - strip.positions[0], e2 = strip.positions[around + 1] - strip.positions[0];
  ASSERT_GT(glm::dot(glm::cross(e2, e1), strip.normals[0]), 0.0f);
  const glm::mat3 quarter = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)));
  HeadMesh turnedStrip = strip;
  for (glm::vec3& p : turnedStrip.positions) p = quarter * p;
  for (glm::vec3& n : turnedStrip.normals) n = quarter * n;
  const SkinTransfer a = computeSkinTransfer(strip, {256, 4}), b = computeSkinTransfer(turnedStrip, {256, 4});
  float worst = 0.0f, hidden = 0.0f;
  for (std::size_t v = 0; v < std::size_t((around + 1) * (up + 1)); ++v) {
    EnvironmentSH sh{};
    for (std::size_t i = 0; i < 9; ++i) sh[i] = glm::dvec3(a.occluded[v][i], 0.0, 0.0);
    const EnvironmentSH expected = rotateEnvironment(sh, glm::transpose(glm::dmat3(quarter)));  // w -> O(R^T w)
    for (std::size_t i = 0; i < 9; ++i) {
      worst = std::max(worst, std::abs(b.occluded[v][i] - float(expected[i].x)));
      hidden = std::max(hidden, std::abs(a.occluded[v][i]));
    }
  }
  std::printf("strip under a ceiling: largest hidden coefficient %.3f, turned mesh differs by %.4f at most\n", hidden, worst);
  EXPECT_GT(hidden, 0.2f) << "the ceiling hides a good part of the lobes";
  EXPECT_LT(worst, 0.05f);
}

TEST(SkinTransfer, TheInsideOfAClosedShellIsDark) {
  HeadMesh mesh = makeEllipsoidMesh({0, 0, 0}, {1.0f, 0.6f, 0.8f}, 24, 12);
  for (glm::vec3& n : mesh.normals) n = -n;  // facing inward
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  const SkinTransfer t = computeSkinTransfer(mesh, {16, 0});
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_EQ(t.blocked[v], 1.0f);
    EXPECT_NEAR(t.reflecting[v], 1.0f, 1e-5f);
    for (std::uint32_t i = 0; i < 9; ++i) {  // 0 to float precision (the hidden part goes through two rotations)
      EXPECT_NEAR(t.direct[v][i], 0.0f, 1e-5f);
      EXPECT_NEAR(t.bounce[v][i], 0.0f, 1e-5f);
    }
  }
  // Smoothed: each vertex's hidden part is its neighbours' mean, taken in their tangent frames, while its open
  // lobe is its own. On this shell (neighbours' normals 15-30 degrees apart) every vertex hides its whole lobe,
  // so nothing may leak: against the lobe's 1.06 at its peak under a unit sun along the normal (sum_l A_l
  // (2l + 1) / (4 pi)), mixed in the mesh's axes instead 0.29 leaked.
  const SkinTransfer smoothed = computeSkinTransfer(mesh);
  float sunLeak = 0.0f, skyLeak = 0.0f;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    EXPECT_EQ(smoothed.blocked[v], 1.0f);
    skyLeak = std::max(skyLeak, std::abs(irradiance(smoothed.direct[v], uniformSky())));
    std::array<float, 9> sun{};
    for (std::uint32_t i = 0; i < 9; ++i) sun[i] = gpu::envShBasis(i, mesh.normals[v]);
    sunLeak = std::max(sunLeak, std::abs(irradiance(smoothed.direct[v], sun)));
  }
  std::printf("closed shell, smoothed: the most a vertex receives of a unit sun along its normal %.4f, of a "
              "uniform sky of radiance 1 %.2g\n", sunLeak, skyLeak);
  EXPECT_LT(skyLeak, 1e-4f);
  EXPECT_LT(sunLeak, 1e-4f);
}

TEST(SkinTransfer, TheJawShadesTheThroatOfTheDefaultHead) {
  const HairAsset asset = buildDefaultHeadAsset();
  const HeadMesh& head = asset.head;
  const auto start = std::chrono::steady_clock::now();
  const SkinTransfer t = computeSkinTransfer(head);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("skin transfer: %zu vertices, %zu triangles in %.2f s\n", head.positions.size(), head.indices.size() / 3,
              seconds);
  // On the face's midline (x = 0, facing forward): the forehead (above y = 0.05) is open to the sky; the throat
  // just under the chin (y -0.16 to -0.12) has the jaw over it, and its skin passes light on to the throat.
  float foreheadBlocked = 1.0f, throatBlocked = 0.0f, throatSky = 0.0f, throatBounce = 0.0f;
  for (std::size_t v = 0; v < head.positions.size(); ++v) {
    const glm::vec3 p = head.positions[v], n = head.normals[v];
    if (std::abs(p.x) > 0.003f || n.z < 0.3f) continue;
    if (p.y > 0.05f) foreheadBlocked = std::min(foreheadBlocked, t.blocked[v]);
    if (p.y > -0.16f && p.y < -0.12f && t.blocked[v] > throatBlocked)
      throatBlocked = t.blocked[v], throatSky = irradiance(t.direct[v], uniformSky()),
      throatBounce = irradiance(t.bounce[v], uniformSky());
  }
  std::printf("forehead blocked %.3f; throat blocked %.3f, sky %.3f, bounce %.3f (a uniform sky of radiance 1)\n",
              foreheadBlocked, throatBlocked, throatSky, throatBounce);
  EXPECT_LT(foreheadBlocked, 0.01f);
  EXPECT_GT(throatBlocked, 0.2f);
  EXPECT_LT(throatSky, 0.85f * kPi);
  EXPECT_GT(throatBounce, 0.1f * throatBlocked * kPi) << "the jaw's lit skin sends light back";
}
