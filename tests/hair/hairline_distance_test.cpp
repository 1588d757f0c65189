// Distances from the hairline (engine/core/hair/hairline_distance.h) on hand-made triangulations: a flat
// square grid, whose open boundary is its rim; the same grid with a parting cut into it and a hole, which are
// not hairline; a closed tetrahedron, which has none; a degenerate triangle.
#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <cmath>
#include <functional>

#include "engine/core/hair/hairline_distance.h"
#include "engine/core/hair/strand_topology.h"

using namespace hp;

namespace {
// An n x n grid of points 1 apart in the xz plane, two triangles per cell.
struct Grid {
  std::vector<glm::vec3> points;
  std::vector<glm::uvec3> triangles;
};
// Cells for which `skip(x, z)` holds are left out.
Grid grid(std::uint32_t n, const std::function<bool(std::uint32_t, std::uint32_t)>& skip = {}) {
  Grid g;
  for (std::uint32_t z = 0; z < n; ++z)
    for (std::uint32_t x = 0; x < n; ++x) g.points.emplace_back(float(x), 0.0f, float(z));
  for (std::uint32_t z = 0; z + 1 < n; ++z)
    for (std::uint32_t x = 0; x + 1 < n; ++x) {
      if (skip && skip(x, z)) continue;
      const std::uint32_t a = z * n + x, b = a + 1, c = a + n, d = c + 1;
      g.triangles.emplace_back(a, b, d);
      g.triangles.emplace_back(a, d, c);
    }
  return g;
}

glm::vec3 centroid(const Grid& g, std::size_t t) {
  const glm::uvec3 v = g.triangles[t];
  return (g.points[v.x] + g.points[v.y] + g.points[v.z]) / 3.0f;
}
}  // namespace

// On an 11 x 11 grid (the rim at 0 and 10) every triangle's distance lies between the straight distance of
// its centroid to the rim and the path through the triangles (at most ~1.5x on this mesh); it grows toward
// the middle; a triangle on the rim is within its own size of it.
TEST(HairlineDistance, GrowsFromTheGridsRimToItsMiddle) {
  const Grid g = grid(11);
  const std::vector<float> d = hairlineDistances(g.points, g.triangles);
  ASSERT_EQ(d.size(), g.triangles.size());
  float largest = 0.0f;
  for (std::size_t t = 0; t < d.size(); ++t) {
    const glm::vec3 c = centroid(g, t);
    const float straight = std::min({c.x, 10.0f - c.x, c.z, 10.0f - c.z});
    ASSERT_GE(d[t], straight - 1e-4f) << "triangle " << t;
    ASSERT_LE(d[t], 1.5f * straight + 0.75f) << "triangle " << t;
    largest = std::max(largest, d[t]);
  }
  EXPECT_GT(largest, 4.0f);  // the middle: 5 from every side
  EXPECT_LT(d[0], 1.0f);     // a corner cell
}

// A parting (a column of cells cut from the rim to the middle, x = 10, z < 12) and a hole (2 x 2 cells at
// x 4-5, z 14-15) in a 21 x 21 grid are not the hairline (the roots across them mark them as gaps in the
// hair): no triangle is nearer than its straight distance to the rim (counted as hairline, the cut's sides
// would be within 0.5). Paths around the cut make some longer: measured at most 2.13 more.
TEST(HairlineDistance, APartingAndAHoleAreNotTheHairline) {
  const Grid g = grid(21, [](std::uint32_t x, std::uint32_t z) {
    return (x == 10 && z < 12) || (x >= 4 && x <= 5 && z >= 14 && z <= 15);
  });
  const std::vector<float> d = hairlineDistances(g.points, g.triangles);
  float worst = 0.0f;
  for (std::size_t t = 0; t < d.size(); ++t) {
    const glm::vec3 c = centroid(g, t);
    const float straight = std::min({c.x, 20.0f - c.x, c.z, 20.0f - c.z});
    ASSERT_LT(d[t], kNoHairline) << "triangle " << t;
    ASSERT_GE(d[t], straight - 1e-4f) << "triangle " << t << " at " << c.x << ", " << c.z;
    worst = std::max(worst, d[t] - straight);
  }
  std::cout << "largest excess over the straight distance to the rim: " << worst << "\n";
  EXPECT_LT(worst, 3.0f);
}

TEST(HairlineDistance, AClosedSurfaceAndADegenerateTriangleHaveNoHairline) {
  const std::vector<glm::vec3> tetra = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<glm::uvec3> closed = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {0, 2, 3}};
  for (float d : hairlineDistances(tetra, closed)) EXPECT_EQ(d, kNoHairline);
  const std::vector<glm::uvec3> withDegenerate = {{0, 1, 2}, {3, 3, 3}};
  const std::vector<float> d = hairlineDistances(tetra, withDegenerate);
  EXPECT_LT(d[0], 1.0f);  // a lone triangle is all rim
  EXPECT_EQ(d[1], kNoHairline);
}

// Roots 1e38 apart (a hostile file's; the fuzzers found the grid's cell index overflowing an int) and a
// sliver: every distance is a number, none undefined behaviour (the sanitizer build runs this).
TEST(HairlineDistance, RootsFarApartAndSliversAreHandled) {
  const std::vector<glm::vec3> roots = {{0, 0, 0}, {1e-3f, 0, 0}, {0, 1e-3f, 0}, {3e38f, 0, 0}, {-3e38f, 1, 0},
                                        {0, 0, 1e-30f}};
  const std::vector<glm::uvec3> triangles = {{0, 1, 2}, {0, 3, 4}, {0, 1, 5}};
  const std::vector<float> d = hairlineDistances(roots, triangles);
  ASSERT_EQ(d.size(), triangles.size());
  for (float v : d) EXPECT_FALSE(std::isnan(v));
}

// buildInterpolationTopology fills one distance per triangle, the same as the function's.
TEST(HairlineDistance, TheInterpolationTopologyCarriesThem) {
  const Grid g = grid(6);
  DensityOptions density;
  density.totalStrands = 200;
  const InterpolationTopology topo = buildInterpolationTopology(g.points, g.triangles, density);
  EXPECT_EQ(topo.hairlineDistance, hairlineDistances(g.points, g.triangles));
}
