// Mesh simplification (engine/core/hair/mesh_simplify.h): the default head's render mesh against its
// marching-cubes source and the field, and small meshes whose answer is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/head_sdf.h"
#include "engine/core/hair/mesh_simplify.h"

namespace hp {
namespace {
struct Source {
  HeadMesh marched;  // scalp marked, as simplifyDefaultHeadMesh takes it
  HeadMesh drawn;
};
const Source& source() {
  static const Source s = [] {
    Source out;
    out.marched = makeDefaultHeadMesh(makeDefaultHeadField());
    markScalp(out.marched, makeDefaultScalp().positions);
    out.drawn = simplifyDefaultHeadMesh(out.marched);
    return out;
  }();
  return s;
}

glm::uvec3 triangle(const HeadMesh& m, std::size_t t) { return {m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]}; }

// Every edge in exactly two triangles, once each way (closed, manifold, consistently wound).
void expectClosedAndWound(const HeadMesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(m, t);
    for (int k = 0; k < 3; ++k) ++directed[{tri[k], tri[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " wound the same way twice";
    ASSERT_TRUE(directed.count({edge.second, edge.first})) << "open edge " << edge.first << "-" << edge.second;
  }
}

double minNormalDot(const HeadMesh& m, const glm::uvec3& t) {
  const glm::vec3 &a = m.normals[t.x], &b = m.normals[t.y], &c = m.normals[t.z];
  return std::min({glm::dot(a, b), glm::dot(a, c), glm::dot(b, c)});
}

// A flat square grid of n x n quads in z = 0, normals +z, counter-clockwise seen from +z; `bump` raises the
// centre vertex (and tilts nothing else).
HeadMesh grid(std::uint32_t n, float bump = 0.0f) {
  HeadMesh m;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const bool centre = i == n / 2 && j == n / 2;
      m.positions.emplace_back(float(i), float(j), centre ? bump : 0.0f);
      m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

double area(const HeadMesh& m) {
  double sum = 0.0;
  for (std::size_t t = 0; t < m.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(m, t);
    sum += 0.5 * glm::length(glm::cross(m.positions[tri.y] - m.positions[tri.x], m.positions[tri.z] - m.positions[tri.x]));
  }
  return sum;
}

TEST(MeshSimplify, DefaultHeadKeepsUnderAThirdOfItsTrianglesClosedAndWound) {
  const Source& s = source();
  const std::size_t before = s.marched.indices.size() / 3, after = s.drawn.indices.size() / 3;
  EXPECT_LT(after * 3, before) << before << " -> " << after;
  EXPECT_GT(after * 10, before) << before << " -> " << after;  // the bounds stop it, not a collapse to nothing
  expectClosedAndWound(s.drawn);
}

TEST(MeshSimplify, DefaultHeadKeepsItsVerticesExactlyItsHairlineAndItsCreasesWhole) {
  const Source& s = source();
  std::map<std::tuple<float, float, float>, std::uint32_t> at;
  for (std::uint32_t i = 0; i < s.marched.positions.size(); ++i)
    at[{s.marched.positions[i].x, s.marched.positions[i].y, s.marched.positions[i].z}] = i;
  std::vector<std::uint32_t> original(s.drawn.positions.size());
  for (std::uint32_t i = 0; i < s.drawn.positions.size(); ++i) {
    const auto found = at.find({s.drawn.positions[i].x, s.drawn.positions[i].y, s.drawn.positions[i].z});
    ASSERT_NE(found, at.end()) << "vertex " << i << " is not one of the source's";
    original[i] = found->second;
    EXPECT_EQ(s.drawn.normals[i], s.marched.normals[found->second]);
    EXPECT_EQ(s.drawn.scalp[i], s.marched.scalp[found->second]);
  }
  // Every uneven source triangle is drawn as it was: across the hairline (scalp weights that differ) or with
  // vertex normals further apart than the bound (the ears' and nostrils' roots, the lips).
  std::set<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> drawn;
  for (std::size_t t = 0; t < s.drawn.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(s.drawn, t);
    drawn.insert({original[tri.x], original[tri.y], original[tri.z]});
  }
  const double minCos = std::cos(glm::radians(double(kDefaultHeadMeshNormalDegrees)));
  std::size_t hairline = 0, creases = 0;
  for (std::size_t t = 0; t < s.marched.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(s.marched, t);
    const bool across = s.marched.scalp[tri.x] != s.marched.scalp[tri.y] || s.marched.scalp[tri.x] != s.marched.scalp[tri.z];
    const bool sharp = minNormalDot(s.marched, tri) < minCos;
    if (!across && !sharp) continue;
    hairline += across;
    creases += sharp;
    EXPECT_TRUE(drawn.count({tri.x, tri.y, tri.z})) << "uneven source triangle " << t << " was reshaped";
  }
  EXPECT_GT(hairline, 500u);
  EXPECT_GT(creases, 100u);
}

TEST(MeshSimplify, DefaultHeadStaysOnTheFieldAndItsShadingClose) {
  // The field's distance at the centroids and edge midpoints of the triangles the simplification made, against
  // the worst of the source's even triangles (those it may reshape; the 4 mm grid's own error, largest at the
  // chest's crease, is on uneven ones, which are drawn as they were) plus the bound.
  const Source& s = source();
  const double minCos = std::cos(glm::radians(double(kDefaultHeadMeshNormalDegrees))) - 1e-6;
  const auto off = [](const HeadMesh& m, const glm::uvec3& tri) {
    const glm::vec3 a = m.positions[tri.x], b = m.positions[tri.y], c = m.positions[tri.z];
    double worst = 0.0;
    for (const glm::vec3& p : {(a + b + c) / 3.0f, 0.5f * (a + b), 0.5f * (b + c), 0.5f * (a + c)})
      worst = std::max(worst, double(std::abs(headDistance(p))));
    return worst;
  };
  std::set<std::tuple<float, float, float, float, float, float, float, float, float>> sourceTriangles;
  const auto key = [](const HeadMesh& m, const glm::uvec3& t) {
    const glm::vec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    return std::tuple{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z};
  };
  double sourceWorst = 0.0;
  for (std::size_t t = 0; t < s.marched.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(s.marched, t);
    sourceTriangles.insert(key(s.marched, tri));
    const bool even = s.marched.scalp[tri.x] == s.marched.scalp[tri.y] && s.marched.scalp[tri.x] == s.marched.scalp[tri.z] &&
                      minNormalDot(s.marched, tri) >= minCos;
    if (even) sourceWorst = std::max(sourceWorst, off(s.marched, tri));
  }
  double madeWorst = 0.0;
  std::size_t made = 0, wide = 0;
  for (std::size_t t = 0; t < s.drawn.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(s.drawn, t);
    if (sourceTriangles.count(key(s.drawn, tri))) continue;
    ++made;
    madeWorst = std::max(madeWorst, off(s.drawn, tri));
    wide += minNormalDot(s.drawn, tri) < minCos;  // the shading across a made triangle stays close
  }
  EXPECT_GT(made, 5000u);
  EXPECT_LE(madeWorst, sourceWorst + kDefaultHeadMeshError) << "source's even triangles: " << sourceWorst << " m";
  EXPECT_EQ(wide, 0u);
  std::cout << "made triangles " << made << ": worst " << madeWorst * 1e3 << " mm off the field (source's even "
            << sourceWorst * 1e3 << " mm)\n";
}

// Simplified here, not through the disk cache CTest gives the tests (which simplifyDefaultHeadMesh reads): the
// same mesh as the drawn one, whether that one was simplified in this process or read from an entry.
TEST(MeshSimplify, DefaultHeadIsDeterministic) {
  const HeadMesh again = simplifyMesh(source().marched, kDefaultHeadSimplify);
  EXPECT_EQ(again.positions, source().drawn.positions);
  EXPECT_EQ(again.indices, source().drawn.indices);
}

TEST(MeshSimplify, FlatGridCollapsesInsideItsLockedBorder) {
  const HeadMesh flat = grid(16);
  const HeadMesh out = simplifyMesh(flat, {0.0f, 1.0f, 0});
  EXPECT_LT(out.indices.size() / 3, flat.indices.size() / 3 / 4);
  EXPECT_NEAR(area(out), 256.0, 1e-3);  // no fold, no hole
  // Every border vertex is kept (an open edge locks its ends), every triangle faces +z.
  std::set<std::pair<float, float>> kept;
  for (const glm::vec3& p : out.positions) kept.insert({p.x, p.y});
  for (std::uint32_t i = 0; i <= 16; ++i)
    for (const auto& p : {std::pair{float(i), 0.0f}, {float(i), 16.0f}, {0.0f, float(i)}, {16.0f, float(i)}})
      EXPECT_TRUE(kept.count(p)) << p.first << ", " << p.second;
  for (std::size_t t = 0; t < out.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(out, t);
    EXPECT_GT(glm::cross(out.positions[tri.y] - out.positions[tri.x], out.positions[tri.z] - out.positions[tri.x]).z, 0.0f);
  }
}

TEST(MeshSimplify, TheErrorBoundKeepsABumpAndTheTargetStopsEarly) {
  const HeadMesh bumped = grid(16, 0.5f);
  const auto hasBump = [](const HeadMesh& m) {
    return std::any_of(m.positions.begin(), m.positions.end(), [](const glm::vec3& p) { return p.z > 0.0f; });
  };
  EXPECT_TRUE(hasBump(simplifyMesh(bumped, {0.1f, 180.0f, 0})));
  EXPECT_FALSE(hasBump(simplifyMesh(bumped, {3.0f, 180.0f, 0})));  // within the bound it may go
  const HeadMesh out = simplifyMesh(grid(16), {0.0f, 1.0f, 300});
  EXPECT_GE(out.indices.size() / 3, 299u);  // a collapse takes two triangles
  EXPECT_LE(out.indices.size() / 3, 300u);
}

TEST(MeshSimplify, NormalsApartLockTheirTriangles) {
  HeadMesh bent = grid(8);
  for (std::size_t i = 0; i < bent.normals.size(); ++i)
    if (bent.positions[i].x >= 4.0f) bent.normals[i] = glm::normalize(glm::vec3(0.5f, 0.0f, 1.0f));  // 26.6 degrees
  const HeadMesh out = simplifyMesh(bent, {0.0f, 10.0f, 0});
  EXPECT_LT(out.indices.size(), bent.indices.size());
  for (std::size_t t = 0; t < out.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(out, t);
    const float x[3] = {out.positions[tri.x].x, out.positions[tri.y].x, out.positions[tri.z].x};
    // A triangle that spans the bend spans one column of quads (x 3 to 4): the source's own.
    if (minNormalDot(out, tri) < std::cos(glm::radians(10.0)))
      EXPECT_LE(*std::max_element(x, x + 3) - *std::min_element(x, x + 3), 1.0f);
  }
}

TEST(MeshSimplify, ReshapedTrianglesKeepTheirNormalsClose) {
  // Normals turning 6 degrees per column: every source triangle is even under a 10 degree bound, so every
  // vertex may move, but no triangle may come to span more than one column.
  HeadMesh turning = grid(12);
  for (std::size_t i = 0; i < turning.normals.size(); ++i) {
    const float angle = glm::radians(6.0f * turning.positions[i].x);
    turning.normals[i] = glm::vec3(std::sin(angle), 0.0f, std::cos(angle));
  }
  const HeadMesh out = simplifyMesh(turning, {0.0f, 10.0f, 0});
  EXPECT_LT(out.indices.size(), turning.indices.size());
  for (std::size_t t = 0; t < out.indices.size() / 3; ++t) {
    const glm::uvec3 tri = triangle(out, t);
    const float x[3] = {out.positions[tri.x].x, out.positions[tri.y].x, out.positions[tri.z].x};
    EXPECT_LE(*std::max_element(x, x + 3) - *std::min_element(x, x + 3), 1.0f) << "triangle " << t;
  }
}

TEST(MeshSimplify, AClosedTetrahedronDoesNotFoldFlat) {
  // A flat tetrahedron with every normal +z and the bounds wide open: the apex passes every other test on its way
  // onto a base vertex (its edge's rings meet at the other two), but that would leave the base twice, back to
  // back. So nothing moves.
  HeadMesh tetrahedron;
  for (const glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.3f, 0.3f, 0.01f)}) {
    tetrahedron.positions.push_back(p);
    tetrahedron.normals.emplace_back(0.0f, 0.0f, 1.0f);
  }
  tetrahedron.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
  expectClosedAndWound(tetrahedron);
  const HeadMesh out = simplifyMesh(tetrahedron, {100.0f, 180.0f, 0});
  EXPECT_EQ(out.positions.size(), 4u);
  EXPECT_EQ(out.indices.size(), 12u);
  expectClosedAndWound(out);
}

TEST(MeshSimplify, BadInputIsNamed) {
  const HeadMesh flat = grid(2);
  const auto message = [](const HeadMesh& m, SimplifyOptions o) {
    try {
      simplifyMesh(m, o);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(flat, {-1.0f}).find("maxError"), std::string::npos);
  EXPECT_NE(message(flat, {std::numeric_limits<float>::quiet_NaN()}).find("maxError"), std::string::npos);
  EXPECT_NE(message(flat, {0.0f, 200.0f}).find("maxNormalDegrees"), std::string::npos);
  HeadMesh partial = flat;
  partial.indices.pop_back();
  EXPECT_NE(message(partial, {}).find("whole triangles"), std::string::npos);
  HeadMesh past = flat;
  past.indices[0] = 99;
  EXPECT_NE(message(past, {}).find("index 99"), std::string::npos);
  HeadMesh normals = flat;
  normals.normals.pop_back();
  EXPECT_NE(message(normals, {}).find("normals"), std::string::npos);
  HeadMesh nan = flat;
  nan.positions[3].y = std::numeric_limits<float>::infinity();
  EXPECT_NE(message(nan, {}).find("vertex 3"), std::string::npos);
  HeadMesh badNormal = flat;
  badNormal.normals[2] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
  EXPECT_NE(message(badNormal, {}).find("normal 2 is not a unit vector"), std::string::npos);
  badNormal.normals[2] = glm::vec3(0.0f, 0.0f, 2.0f);
  EXPECT_NE(message(badNormal, {}).find("normal 2 is not a unit vector"), std::string::npos);
  HeadMesh scalp = flat;
  scalp.scalp = {1.0f};
  EXPECT_NE(message(scalp, {}).find("1 scalp weights for 9 positions"), std::string::npos);
  HeadMesh unused = flat;
  unused.indices.clear();
  EXPECT_TRUE(simplifyMesh(unused, {}).positions.empty());  // no triangle uses a vertex
}
}  // namespace
}  // namespace hp
