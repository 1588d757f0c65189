// Interpolation topology: fold barycentrics (and their uniformity), density, determinism; the convex
// hull, the sphere fit and the root triangulation used for imported models.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numeric>

#include "engine/core/hair/convex_hull.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/rng.h"
#include "engine/core/hair/root_topology.h"
#include "engine/core/hair/strand_topology.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
// Chi-square statistic of barycentric samples over the n*n congruent sub-triangles of the triangle.
double chiSquareOverSubTriangles(const std::vector<glm::vec3>& samples, int n) {
  std::vector<int> count(2 * n * n, 0);
  for (const auto& x : samples) {
    double a = x.x * n, b = x.y * n;
    int i = std::min(int(a), n - 1), j = std::min(int(b), n - 1);
    bool down = (a - i) + (b - j) >= 1.0 && i + j <= n - 2;
    ++count[(down ? n * n : 0) + i * n + j];
  }
  double expected = double(samples.size()) / (n * n), chi2 = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (i + j <= n - 1) chi2 += std::pow(count[i * n + j] - expected, 2) / expected;
      if (i + j <= n - 2) chi2 += std::pow(count[n * n + i * n + j] - expected, 2) / expected;
    }
  return chi2;
}

// 16 cells, 15 degrees of freedom: P(chi2 > 40) is about 5e-4 for a uniform sampler.
constexpr int kCells = 4;
constexpr double kChi2Threshold = 40.0;
constexpr std::uint32_t kSamples = 32000;

TEST(TopologyFold, BarycentricsSumToOneAndAreNonNegative) {
  for (std::uint32_t i = 0; i < 10000; ++i) {
    glm::vec3 x = foldBarycentric(hashRandom(5, i, 1), hashRandom(5, i, 2));
    EXPECT_NEAR(x.x + x.y + x.z, 1.0f, 1e-6f);
    EXPECT_GE(x.x, 0.0f);
    EXPECT_GE(x.y, 0.0f);
    EXPECT_GE(x.z, 0.0f);
  }
  EXPECT_EQ(foldBarycentric(0.75f, 0.5f), glm::vec3(0.25f, 0.5f, 0.25f));  // folded
}

TEST(TopologyFold, IsUniformOverTheTriangle) {
  std::vector<glm::vec3> samples;
  for (std::uint32_t i = 0; i < kSamples; ++i) samples.push_back(foldBarycentric(hashRandom(11, i, 1), hashRandom(11, i, 2)));
  EXPECT_LT(chiSquareOverSubTriangles(samples, kCells), kChi2Threshold);
}

TEST(TopologyFold, TheCheckCatchesTheNaiveNormalizedSampler) {
  // X_i = r_i / (r_1 + r_2 + r_3) piles samples toward the centroid: the same check must fail it.
  std::vector<glm::vec3> samples;
  for (std::uint32_t i = 0; i < kSamples; ++i) {
    glm::vec3 r(hashRandom(11, i, 1), hashRandom(11, i, 2), hashRandom(11, i, 3));
    samples.push_back(r / (r.x + r.y + r.z));
  }
  EXPECT_GT(chiSquareOverSubTriangles(samples, kCells), kChi2Threshold);
}

TEST(TopologyFold, TopologyStrandsAreUniformToo) {
  std::vector<glm::vec3> roots{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  DensityOptions d;
  d.totalStrands = kSamples;
  InterpolationTopology t = buildInterpolationTopology(roots, {{0, 1, 2}}, d);
  std::vector<glm::vec3> samples;
  for (const auto& s : t.strands) samples.push_back(s.barycentric);
  EXPECT_LT(chiSquareOverSubTriangles(samples, kCells), kChi2Threshold);
}

TEST(TopologyDensity, TotalIsExactAndFollowsArea) {
  std::vector<glm::vec3> roots{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {3, 0, 0}, {0, 3, 0}};
  std::vector<glm::uvec3> tris{{0, 1, 2}, {1, 3, 4}};  // areas 0.5 and 3
  DensityOptions d;
  d.totalStrands = 701;
  auto counts = strandsPerTriangle(roots, tris, d);
  EXPECT_EQ(counts[0] + counts[1], 701u);
  EXPECT_NEAR(double(counts[1]) / counts[0], 6.0, 0.1);
  d.mode = DensityOptions::Mode::PerTriangle;
  d.strandsPerTriangle = 5;
  EXPECT_EQ(strandsPerTriangle(roots, tris, d), (std::vector<std::uint32_t>{5, 5}));
}

// Level-of-detail order: every prefix of the strands holds each triangle's share (within 1 + 3 x share
// strands: each triangle's count is within one of its stratum, the prefix length within three), so drawing
// the first fraction thins all of the scalp evenly.
TEST(TopologyDensity, EveryPrefixHoldsEachTrianglesShareAndIsDeterministic) {
  std::vector<glm::vec3> roots{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {3, 0, 0}};
  DensityOptions d;
  d.mode = DensityOptions::Mode::PerTriangle;
  d.strandsPerTriangle = 50;
  auto a = buildInterpolationTopology(roots, {{0, 1, 2}, {1, 3, 2}}, d);
  auto b = buildInterpolationTopology(roots, {{0, 1, 2}, {1, 3, 2}}, d);
  ASSERT_EQ(a.strands.size(), 100u);
  for (std::size_t i = 0; i < a.strands.size(); ++i) {
    EXPECT_EQ(a.strands[i].triangle, b.strands[i].triangle);
    EXPECT_EQ(a.strands[i].barycentric, b.strands[i].barycentric);
    EXPECT_EQ(a.strands[i].random, b.strands[i].random);
  }
  d.mode = DensityOptions::Mode::Total;  // triangle areas 0.5, 0.5, 1: 75, 75 and 150 strands
  d.totalStrands = 300;
  auto lod = buildInterpolationTopology(roots, {{0, 1, 2}, {1, 3, 2}, {1, 4, 3}}, d);
  const double share[] = {0.25, 0.25, 0.5};
  std::vector<double> seen(3, 0.0);
  for (std::size_t n = 1; n <= lod.strands.size(); ++n) {
    seen[lod.strands[n - 1].triangle] += 1.0;
    for (int t = 0; t < 3; ++t) {
      const double off = std::abs(seen[t] - share[t] * double(n));
      EXPECT_LE(off, 1.0 + 3.0 * share[t]) << "prefix " << n << ", triangle " << t;
    }
  }
  // Not the order of generation (triangle after triangle): the first ten strands span all three.
  std::vector<bool> first10(3, false);
  for (int i = 0; i < 10; ++i) first10[lod.strands[i].triangle] = true;
  EXPECT_TRUE(first10[0] && first10[1] && first10[2]);
  d.seed = 8;
  auto c = buildInterpolationTopology(roots, {{0, 1, 2}, {1, 3, 2}}, d);
  EXPECT_NE(a.strands[0].barycentric, c.strands[0].barycentric);
}

TEST(TopologyDensity, RejectsBadInput) {
  std::vector<glm::vec3> roots{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_ERROR_CONTAINS(buildInterpolationTopology(roots, {}, {}), "interpolation topology: no triangles");
  EXPECT_ERROR_CONTAINS(buildInterpolationTopology(roots, {{0, 1, 3}}, {}), "triangle 0 names a guide beyond 3");
  DensityOptions d;
  d.totalStrands = 0;
  EXPECT_ERROR_CONTAINS(d.validate(), "density: totalStrands must be in [1, ");
  d = {};
  d.strandsPerTriangle = 0;
  EXPECT_ERROR_CONTAINS(d.validate(), "density: strandsPerTriangle must be in [1, 4096], got 0");
  // Within bounds per triangle, past them in all: 4,097 triangles x 4,096 strands is refused before binding.
  d = {};
  d.mode = DensityOptions::Mode::PerTriangle;
  d.strandsPerTriangle = 4096;
  const std::vector<glm::uvec3> many(4097, glm::uvec3(0, 1, 2));
  EXPECT_ERROR_CONTAINS(buildInterpolationTopology(roots, many, d),
                        "density: strandsPerTriangle 4096 on 4097 scalp triangles makes 16781312 strands, more than the "
                        "16777216 allowed");
  const std::vector<glm::uvec3> fewer(4096, glm::uvec3(0, 1, 2));
  d.strandsPerTriangle = 1;
  EXPECT_EQ(buildInterpolationTopology(roots, fewer, d).strands.size(), 4096u);
}

std::vector<glm::dvec3> fibonacci(int n) {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < n; ++i) {
    double y = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1 - y * y), phi = 2.399963229728653 * i;
    p.emplace_back(r * std::cos(phi), y, r * std::sin(phi));
  }
  return p;
}

// Every undirected edge used by exactly `uses` triangles (2: closed surface).
bool everyEdgeUsedAtMost(const std::vector<glm::uvec3>& tris, int uses, bool exactly) {
  std::map<std::pair<unsigned, unsigned>, int> edges;
  for (const auto& t : tris)
    for (int k = 0; k < 3; ++k) ++edges[std::minmax(t[k], t[(k + 1) % 3])];
  for (const auto& [e, n] : edges)
    if (n > uses || (exactly && n != uses)) return false;
  return true;
}

TEST(TopologyHull, CubeWithInteriorPoints) {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  for (int i = 0; i < 50; ++i) p.emplace_back(0.1 + 0.8 * hashRandom(1, i, 0), 0.1 + 0.8 * hashRandom(1, i, 1), 0.5);
  auto hull = convexHull(p);
  EXPECT_EQ(hull.size(), 12u);
  for (const auto& t : hull) EXPECT_TRUE(glm::all(glm::lessThan(t, glm::uvec3(8))));
  EXPECT_TRUE(everyEdgeUsedAtMost(hull, 2, true));
}

TEST(TopologyHull, SpherePointsAreAllOnAClosedOutwardHull) {
  auto p = fibonacci(2000);
  p.push_back(p[10]);  // a duplicate is no extra vertex
  auto hull = convexHull(p);
  EXPECT_EQ(hull.size(), 2u * 2000u - 4u);
  EXPECT_TRUE(everyEdgeUsedAtMost(hull, 2, true));
  for (const auto& t : hull) {
    glm::dvec3 n = glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]);
    EXPECT_GT(glm::dot(n, p[t.x] + p[t.y] + p[t.z]), 0.0);
  }
}

TEST(TopologyHull, RandomPointsAreInsideEveryFace) {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < 3000; ++i) p.emplace_back(hashRandom(2, i, 0), hashRandom(2, i, 1), hashRandom(2, i, 2));
  auto hull = convexHull(p);
  ASSERT_FALSE(hull.empty());
  EXPECT_TRUE(everyEdgeUsedAtMost(hull, 2, true));
  for (const auto& t : hull) {
    glm::dvec3 n = glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
    for (const auto& q : p) ASSERT_LE(glm::dot(n, q - p[t.x]), 1e-9);
  }
}

TEST(TopologyHull, DegenerateInputGivesNoHull) {
  EXPECT_TRUE(convexHull(std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).empty());
  std::vector<glm::dvec3> flat;
  for (int i = 0; i < 100; ++i) flat.emplace_back(hashRandom(3, i, 0), hashRandom(3, i, 1), 2.0);
  EXPECT_TRUE(convexHull(flat).empty());
}

TEST(TopologySphereFit, RecoversASphereFromACap) {
  std::vector<glm::vec3> p;
  for (const auto& d : fibonacci(3000))
    if (d.y > 0.3) p.push_back(glm::vec3(1, 2, 3) + glm::vec3(d) * 0.5f);
  SphereFit fit = fitSphere(p);
  EXPECT_TRUE(fit.fitted);
  EXPECT_NEAR(glm::distance(fit.sphere.center, glm::vec3(1, 2, 3)), 0.0f, 1e-4f);
  EXPECT_NEAR(fit.sphere.radius, 0.5f, 1e-4f);
  EXPECT_LT(fit.rmsError, 1e-4f);
}

TEST(TopologySphereFit, FlatPointsGiveAStandInBelow) {
  std::vector<glm::vec3> p;
  for (int i = 0; i < 100; ++i) p.emplace_back(hashRandom(3, i, 0), 1.0f, hashRandom(3, i, 1));
  SphereFit fit = fitSphere(p);
  EXPECT_FALSE(fit.fitted);
  EXPECT_LT(fit.sphere.center.y, 1.0f);
  EXPECT_ERROR_CONTAINS(fitSphere(std::vector<glm::vec3>{}), "sphere fit: no points");
}

TEST(TopologyRoots, TriangulatesACapWithoutItsLid) {
  std::vector<glm::vec3> roots;
  for (const auto& d : fibonacci(4000))
    if (d.y > 0.2) roots.push_back(glm::vec3(d) * (0.1f + 0.002f * hashRandom(4, roots.size(), 0)));
  RootTriangulation tri = triangulateRoots(roots, glm::vec3(0.0f));
  EXPECT_GT(tri.droppedFacingAway, 0u);
  EXPECT_TRUE(everyEdgeUsedAtMost(tri.triangles, 2, false));
  double area = 0.0;  // on the unit sphere: must cover the cap, 2 pi (1 - 0.2)
  for (const auto& t : tri.triangles) {
    glm::vec3 a = glm::normalize(roots[t.x]), b = glm::normalize(roots[t.y]), c = glm::normalize(roots[t.z]);
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  EXPECT_NEAR(area / (2.0 * 3.14159265 * 0.8), 1.0, 0.03);
  // Every root is used: on a cap all of them are hull vertices.
  std::vector<bool> used(roots.size(), false);
  for (const auto& t : tri.triangles) used[t.x] = used[t.y] = used[t.z] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), true), static_cast<long>(roots.size()));
}
}  // namespace
}  // namespace hp

namespace hp {
// Own strands (DensityOptions::Mode::Guides): one render strand on every guide, exactly at its corner of a
// triangle that has it; a guide in no triangle gets a triangle of its own; any prefix holds an even share of
// the guides (two halves of the roots); Auto draws own strands from totalStrands guides on.
TEST(Topology, OwnStrandsLieOnEveryGuideOnce) {
  std::vector<glm::vec3> roots;
  for (int i = 0; i < 400; ++i) roots.emplace_back(float(i % 20), float(i / 20), 0.0f);
  std::vector<glm::uvec3> triangles;
  for (std::uint32_t y = 0; y + 1 < 20; ++y)
    for (std::uint32_t x = 0; x + 1 < 10; ++x) {  // the right half of the grid (x >= 10) is in no triangle
      const std::uint32_t a = y * 20 + x;
      triangles.emplace_back(a, a + 1, a + 20);
      triangles.emplace_back(a + 1, a + 21, a + 20);
    }
  DensityOptions d;
  d.mode = DensityOptions::Mode::Guides;
  const InterpolationTopology t = buildInterpolationTopology(roots, triangles, d);
  ASSERT_EQ(t.strands.size(), roots.size());
  std::vector<int> seen(roots.size(), 0);
  for (const StrandBinding& s : t.strands) {
    const glm::uvec3 tri = t.triangles[s.triangle];
    const glm::vec3 at = s.barycentric.x * roots[tri.x] + s.barycentric.y * roots[tri.y] + s.barycentric.z * roots[tri.z];
    int guide = -1;
    for (int k = 0; k < 3; ++k)
      if (s.barycentric[k] == 1.0f) guide = int(tri[k]);
    ASSERT_GE(guide, 0);
    EXPECT_EQ(at, roots[std::size_t(guide)]);
    ++seen[std::size_t(guide)];
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 400);
  EXPECT_GT(t.triangles.size(), triangles.size());  // own triangles for the right half
  std::uint32_t leftOfFirstHalf = 0;
  for (std::size_t i = 0; i < 200; ++i) leftOfFirstHalf += t.strands[i].triangle < triangles.size() ? 1u : 0u;
  EXPECT_NEAR(double(leftOfFirstHalf), 100.0, 25.0);  // about half of the first 200 are in the left half
  const InterpolationTopology again = buildInterpolationTopology(roots, triangles, d);  // deterministic
  for (std::size_t i = 0; i < t.strands.size(); ++i) EXPECT_EQ(again.strands[i].triangle, t.strands[i].triangle);
  d.mode = DensityOptions::Mode::Auto;
  d.totalStrands = 400;
  EXPECT_EQ(resolvedMode(d, roots.size()), DensityOptions::Mode::Guides);
  d.totalStrands = 401;
  EXPECT_EQ(resolvedMode(d, roots.size()), DensityOptions::Mode::Total);
  EXPECT_EQ(buildInterpolationTopology(roots, triangles, d).strands.size(), 401u);
}
}  // namespace hp
