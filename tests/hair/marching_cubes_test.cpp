// The generated marching-cubes table, case by case, and meshes of random fields: every ambiguous
// face configuration occurs, and the mesh must still be closed and consistently wound.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/hair/level_set_mesh.h"
#include "engine/core/hair/marching_cubes_table.h"
#include "engine/core/hair/narrow_band.h"
#include "engine/core/hair/rng.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp {
namespace {
glm::vec3 corner(std::uint32_t n) { return {float(n & 1u), float((n >> 1) & 1u), float((n >> 2) & 1u)}; }
glm::vec3 edgeMidpoint(std::uint32_t e) {
  glm::vec3 p = corner(edgeCorner(e));
  p[int(edgeAxis(e))] = 0.5f;
  return p;
}
bool crossedEdge(std::uint32_t inside, std::uint32_t e) {
  const std::uint32_t u = edgeCorner(e), v = u | (1u << edgeAxis(e));
  return ((inside >> u) & 1u) != ((inside >> v) & 1u);
}

// Directed edges of a triangle list: each once, its reverse once (closed, consistently wound).
std::size_t unpairedEdges(const std::vector<std::uint32_t>& indices) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) ++directed[{indices[t + e], indices[t + (e + 1) % 3]}];
  std::size_t bad = 0;
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    bad += count != 1 || reverse == directed.end() || reverse->second != 1;
  }
  return bad;
}
}  // namespace

TEST(MarchingCubes, EdgesJoinNeighbouringCornersAlongTheirAxis) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> seen;
  for (std::uint32_t e = 0; e < 12; ++e) {
    ASSERT_LT(edgeAxis(e), 3u);
    ASSERT_EQ(edgeCorner(e) & (1u << edgeAxis(e)), 0u) << "edge " << e << " must start at its lower corner";
    ++seen[{edgeCorner(e), edgeAxis(e)}];
  }
  EXPECT_EQ(seen.size(), 12u);
}

TEST(MarchingCubes, EveryCaseUsesExactlyItsCrossedEdges) {
  for (std::uint32_t c = 0; c < 256; ++c) {
    const MarchingCase& mc = marchingCase(c);
    std::uint32_t used = 0, crossed = 0;
    for (std::uint32_t i = 0; i < 3u * mc.triangleCount; ++i) used |= 1u << mc.edges[i];
    for (std::uint32_t e = 0; e < 12; ++e) crossed |= std::uint32_t(crossedEdge(c, e)) << e;
    EXPECT_EQ(used, crossed) << "case " << c;
    EXPECT_LE(mc.triangleCount, 12u);
    if (c == 0 || c == 255) {
      EXPECT_EQ(mc.triangleCount, 0u);
    }
  }
}

TEST(MarchingCubes, DiagonalInsideCornersOfAFaceAreCutOffSeparately) {
  // Corners 0 and 3 are diagonal on the face z = 0: two separate corner triangles, sharing no edge
  // (joining them through the face would make a tunnel, and the cell below would disagree).
  for (std::uint32_t c : {0b1001u, 0b0110u, 0b00010100u}) {  // z = 0 both ways, and corners 2, 4 on x = 0
    const MarchingCase& mc = marchingCase(c);
    ASSERT_EQ(mc.triangleCount, 2u) << "case " << c;
    std::uint32_t first = 0, second = 0;
    for (int k = 0; k < 3; ++k) first |= 1u << mc.edges[k], second |= 1u << mc.edges[3 + k];
    EXPECT_EQ(first & second, 0u) << "case " << c;
  }
}

TEST(MarchingCubes, TrianglesFaceThePositiveSide) {
  // Where one corner, or two along an edge, differ from the rest the surface is a plane-like patch:
  // each triangle (edge midpoints) must face away from the inside corners.
  for (std::uint32_t c = 1; c < 255; ++c) {
    const std::uint32_t minority = __builtin_popcount(c) <= 4 ? c : 255u ^ c;
    const int count = __builtin_popcount(minority);
    const std::uint32_t first = __builtin_ctz(minority), last = 31 - __builtin_clz(minority);
    if (count > 2 || (count == 2 && __builtin_popcount(first ^ last) != 1)) continue;
    glm::vec3 in(0.0f), out(0.0f);
    for (std::uint32_t n = 0; n < 8; ++n) ((c >> n) & 1u ? in : out) += corner(n);
    in /= float(__builtin_popcount(c)), out /= float(8 - __builtin_popcount(c));
    const glm::vec3 outward = out - in;
    const MarchingCase& mc = marchingCase(c);
    ASSERT_GT(mc.triangleCount, 0u) << "case " << c;
    for (std::uint32_t t = 0; t < mc.triangleCount; ++t) {
      const glm::vec3 a = edgeMidpoint(mc.edges[3 * t]), b = edgeMidpoint(mc.edges[3 * t + 1]),
                      d = edgeMidpoint(mc.edges[3 * t + 2]);
      EXPECT_GT(glm::dot(glm::cross(b - a, d - a), outward), 0.0f) << "case " << c << " triangle " << t;
    }
  }
}

TEST(MarchingCubes, RandomFieldsMeshClosedAndConsistentlyWound) {
  // Random node values (every ambiguous face and cell occurs), positive in the grid's four outer layers
  // of nodes (a crossed cell must not touch the boundary, also at stride 2); the exact field is the grid's own trilinear interpolation.
  for (std::uint32_t seed = 1; seed <= 4; ++seed) {
    SdfGrid grid = sampleField([](const glm::vec3&) { return 1.0f; }, glm::vec3(0.0f), glm::vec3(1.8f), 0.1f);
    for (std::uint32_t k = 4; k + 4 < grid.dims.z; ++k)
      for (std::uint32_t j = 4; j + 4 < grid.dims.y; ++j)
        for (std::uint32_t i = 4; i + 4 < grid.dims.x; ++i)
          grid.values[grid.index(i, j, k)] = hashRandom(seed, std::uint32_t(grid.index(i, j, k)), 0) - 0.5f;
    const DistanceFunction field = [&](const glm::vec3& p) { return grid.sample(p); };
    const HeadMesh m = meshZeroLevel(grid, field);
    ASSERT_GT(m.indices.size(), 300u);
    EXPECT_EQ(unpairedEdges(m.indices), 0u) << "seed " << seed;
    for (const glm::vec3& p : m.positions) ASSERT_LT(std::abs(grid.sample(p)), 1e-3f);
    // Every second node: a coarser random field, still closed.
    const HeadMesh coarse = meshZeroLevel(grid, wholeGridBand(grid, field), 2);
    ASSERT_GT(coarse.indices.size(), 30u);
    EXPECT_EQ(unpairedEdges(coarse.indices), 0u) << "seed " << seed << ", stride 2";
  }
}

TEST(MarchingCubes, BricksSkippedByTheirSignsMeshLikeBricksReadNodeByNode) {
  // A ball off the grid's centre on a grid whose last bricks are partial: the band's per-brick signs
  // let the mesher skip bricks unread; without them (empty) it reads every near brick. Same mesh, for
  // several brick sizes and strides.
  sdf::Program ball;
  ball.sphere({0.013f, -0.021f, 0.008f}, 0.31f);
  for (std::uint32_t brick : {1u, 2u, 3u, 4u, 8u, 32u}) {
    const NarrowBandGrid band = sampleNarrowBand(ball, glm::vec3(-0.43f), glm::vec3(0.47f), 0.017f, 0.04f, brick);
    ASSERT_EQ(band.band.signs.size(), band.band.nearSlot.size());
    LevelSetBand unknown = band.band;
    unknown.signs.clear();
    for (std::uint32_t stride : {1u, 2u, 4u}) {
      if (brick % stride != 0) continue;
      const HeadMesh skipped = meshZeroLevel(band.grid, band.band, stride), read = meshZeroLevel(band.grid, unknown, stride);
      ASSERT_GT(skipped.indices.size(), 30u) << "brick " << brick << ", stride " << stride;
      EXPECT_EQ(skipped.indices, read.indices) << "brick " << brick << ", stride " << stride;
      EXPECT_EQ(skipped.positions, read.positions) << "brick " << brick << ", stride " << stride;
      EXPECT_EQ(unpairedEdges(skipped.indices), 0u) << "brick " << brick << ", stride " << stride;
    }
  }
  const NarrowBandGrid ok = sampleNarrowBand(ball, glm::vec3(-0.43f), glm::vec3(0.47f), 0.017f, 0.04f);
  auto expectRefused = [&](const LevelSetBand& band, const std::string& needle) {
    try {
      meshZeroLevel(ok.grid, band);
      ADD_FAILURE() << "accepted; expected a refusal naming " << needle;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  LevelSetBand wrong = ok.band;
  wrong.signs.pop_back();
  expectRefused(wrong, "sign summaries");
  wrong = ok.band;
  wrong.brickCells = 64;
  expectRefused(wrong, "bricks of 1 to 32 cells");
}
}  // namespace hp
