#include "engine/core/hair/sdf_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/number_text.h"

namespace hp {
// Closest point by Voronoi region of the triangle (vertex, edge, face), then its distance.
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const float denom = 1.0f / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return glm::length(p - closestPointOnTriangle(p, a, b, c));
}

namespace {
constexpr std::uint32_t kNoTriangle = 0xffffffffu;
// ~5-10 s of CPU: a body of a million small triangles needs ~1e8 near a grid's default cell.
constexpr std::uint64_t kMaxNearBandTests = 250'000'000;

struct Builder {
  std::span<const glm::vec3> pos;
  std::span<const glm::uvec3> tris;
  SdfGrid g;
  std::vector<std::uint32_t> nearest;

  float distanceTo(std::uint32_t t, const glm::vec3& p) const {
    return pointTriangleDistance(p, pos[tris[t].x], pos[tris[t].y], pos[tris[t].z]);
  }

  glm::uvec3 nodeFloor(const glm::vec3& p) const {
    return glm::uvec3(glm::clamp(glm::floor((p - g.origin) / g.cell), glm::vec3(0.0f), glm::vec3(g.dims - 1u)));
  }
  glm::uvec3 nodeCeil(const glm::vec3& p) const {
    return glm::uvec3(glm::clamp(glm::ceil((p - g.origin) / g.cell), glm::vec3(0.0f), glm::vec3(g.dims - 1u)));
  }

  // Triangle t's near band: the nodes of its box padded by 1.5 cells, [lo, hi].
  std::pair<glm::uvec3, glm::uvec3> bandOf(std::uint32_t t) const {
    const glm::vec3 &a = pos[tris[t].x], &b = pos[tris[t].y], &c = pos[tris[t].z];
    const glm::vec3 pad(1.5f * g.cell);
    return {nodeFloor(glm::min(a, glm::min(b, c)) - pad), nodeCeil(glm::max(a, glm::max(b, c)) + pad)};
  }

  // The near band's point-triangle tests, refused past kMaxNearBandTests before any is made: a few large
  // triangles each spanning much of a fine grid would take minutes (the grid's own size is bounded elsewhere).
  void checkNearBandCost() const {
    std::uint64_t tests = 0;
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
      const auto [lo, hi] = bandOf(t);
      tests += std::uint64_t(hi.x - lo.x + 1) * (hi.y - lo.y + 1) * (hi.z - lo.z + 1);
    }
    if (tests > kMaxNearBandTests)
      throw Error("collider mesh: " + std::to_string(tris.size()) + " triangles at a cell of " + numberText(g.cell) +
                  " need " + std::to_string(tests) + " distance tests near the surface, more than the " +
                  std::to_string(kMaxNearBandTests) + " allowed (a larger cell, or smaller triangles)");
  }

  void nearBand() {
    for (std::uint32_t t = 0; t < tris.size(); ++t) {
      const auto [lo, hi] = bandOf(t);
      for (std::uint32_t k = lo.z; k <= hi.z; ++k)
        for (std::uint32_t j = lo.y; j <= hi.y; ++j)
          for (std::uint32_t i = lo.x; i <= hi.x; ++i) {
            const std::size_t n = g.index(i, j, k);
            const float d = distanceTo(t, g.node(i, j, k));
            if (d < g.values[n]) g.values[n] = d, nearest[n] = t;
          }
    }
  }

  // One sweep in direction s (each component +1 or -1): every node tries the nearest triangles of
  // the three neighbours it has already visited in this sweep.
  void sweep(const glm::ivec3& s) {
    const glm::ivec3 d(g.dims);
    for (int kk = 0; kk < d.z; ++kk)
      for (int jj = 0; jj < d.y; ++jj)
        for (int ii = 0; ii < d.x; ++ii) {
          const glm::ivec3 n(s.x > 0 ? ii : d.x - 1 - ii, s.y > 0 ? jj : d.y - 1 - jj, s.z > 0 ? kk : d.z - 1 - kk);
          const std::size_t here = g.index(n.x, n.y, n.z);
          const glm::vec3 p = g.node(n.x, n.y, n.z);
          for (int axis = 0; axis < 3; ++axis) {
            glm::ivec3 m = n;
            m[axis] -= s[axis];
            if (m[axis] < 0 || m[axis] >= d[axis]) continue;
            const std::uint32_t t = nearest[g.index(m.x, m.y, m.z)];
            if (t == kNoTriangle || t == nearest[here]) continue;
            const float dist = distanceTo(t, p);
            if (dist < g.values[here]) g.values[here] = dist, nearest[here] = t;
          }
        }
  }

  // Parity of crossings along +x for every node row (y_j, z_k), nudged off the grid lines so a ray
  // does not run exactly through shared edges and vertices.
  void sign() {
    std::vector<std::vector<float>> crossings(std::size_t(g.dims.y) * g.dims.z);
    const float nudgeY = 1.37e-4f * g.cell, nudgeZ = 2.91e-4f * g.cell;
    for (const auto& t : tris) {
      const glm::vec3 &a = pos[t.x], &b = pos[t.y], &c = pos[t.z];
      const glm::uvec3 lo = nodeFloor(glm::min(a, glm::min(b, c))), hi = nodeCeil(glm::max(a, glm::max(b, c)));
      for (std::uint32_t k = lo.z; k <= hi.z; ++k)
        for (std::uint32_t j = lo.y; j <= hi.y; ++j) {
          const glm::vec2 q = glm::vec2(g.node(0, j, k).y + nudgeY, g.node(0, j, k).z + nudgeZ);
          // Barycentrics of q in the triangle's yz projection.
          const glm::vec2 A(a.y, a.z), B(b.y, b.z), C(c.y, c.z);
          const float area = (B.x - A.x) * (C.y - A.y) - (C.x - A.x) * (B.y - A.y);
          if (std::abs(area) < 1e-20f) continue;
          const float wb = ((q.x - A.x) * (C.y - A.y) - (C.x - A.x) * (q.y - A.y)) / area;
          const float wc = ((B.x - A.x) * (q.y - A.y) - (q.x - A.x) * (B.y - A.y)) / area;
          if (wb < 0.0f || wc < 0.0f || wb + wc > 1.0f) continue;
          crossings[std::size_t(k) * g.dims.y + j].push_back(a.x + wb * (b.x - a.x) + wc * (c.x - a.x));
        }
    }
    for (std::uint32_t k = 0; k < g.dims.z; ++k)
      for (std::uint32_t j = 0; j < g.dims.y; ++j) {
        auto& xs = crossings[std::size_t(k) * g.dims.y + j];
        std::sort(xs.begin(), xs.end());
        std::size_t passed = 0;
        for (std::uint32_t i = 0; i < g.dims.x; ++i) {
          const float x = g.node(i, j, k).x;
          while (passed < xs.size() && xs[passed] < x) ++passed;
          if (passed % 2 == 1) g.values[g.index(i, j, k)] = -g.values[g.index(i, j, k)];
        }
      }
  }
};
}  // namespace

SdfGrid meshSdf(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles, float cell,
                std::uint32_t padding, std::size_t maxNodes) {
  if (triangles.empty()) throw Error("collider mesh: no triangles");
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const auto& t : triangles)
    for (int v = 0; v < 3; ++v) {
      if (t[v] >= positions.size()) throw Error("collider mesh: a triangle index is out of range");
      const glm::vec3& p = positions[t[v]];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error("collider mesh: a vertex is not finite");
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
  const float extent = std::max(hi.x - lo.x, std::max(hi.y - lo.y, hi.z - lo.z));
  if (!(extent > 0.0f)) throw Error("collider mesh: all vertices are at one point");
  if (!(cell > 0.0f)) cell = extent / 64.0f;
  const glm::vec3 pad(float(padding) * cell);
  Builder b{positions, triangles, {}, {}};
  b.g = sampleField([](const glm::vec3&) { return std::numeric_limits<float>::max(); }, lo - pad, hi + pad, cell,
                    maxNodes);
  b.checkNearBandCost();
  b.nearest.assign(b.g.values.size(), kNoTriangle);
  b.nearBand();
  for (int s = 0; s < 8; ++s) b.sweep({s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1});
  b.sign();
  return std::move(b.g);
}
}  // namespace hp
