// Roots bound to their nearest triangles (docs/THEORY.md §8.6).
#include "engine/core/hair/root_binding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/hair/sdf_mesh.h"

namespace hp {
namespace {
// Triangles bucketed by the grid cells their boxes overlap.
class TriangleGrid {
 public:
  TriangleGrid(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles) {
    for (const auto& p : positions) lo_ = glm::min(lo_, p), hi_ = glm::max(hi_, p);
    const glm::vec3 size = glm::max(hi_ - lo_, glm::vec3(1e-6f));
    // About two triangles per cell, at most 64 cells a side; coarser while the triangles' boxes would make
    // more than kMaxEntries entries (long triangles span many cells).
    const float volume = size.x * size.y * size.z;
    cell_ = std::max(std::cbrt(volume / float(std::max<std::size_t>(triangles.size() / 2, 1))), glm::length(size) / 110.0f);
    dims_ = glm::min(glm::ivec3(size / cell_) + 1, glm::ivec3(64));
    while (entries(positions, triangles) > kMaxEntries && dims_ != glm::ivec3(1)) {
      cell_ *= 2.0f;
      dims_ = glm::max((dims_ + 1) / 2, glm::ivec3(1));
    }
    cells_.resize(std::size_t(dims_.x) * std::size_t(dims_.y) * std::size_t(dims_.z));
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto [from, to] = cellsOf(positions, triangles[t]);
      for (int z = from.z; z <= to.z; ++z)
        for (int y = from.y; y <= to.y; ++y)
          for (int x = from.x; x <= to.x; ++x) cells_[index({x, y, z})].push_back(std::uint32_t(t));
    }
  }
  static constexpr std::uint64_t kMaxEntries = std::uint64_t(1) << 25;
  glm::ivec3 cellOf(const glm::vec3& p) const { return glm::clamp(glm::ivec3(glm::floor((p - lo_) / cell_)), glm::ivec3(0), dims_ - 1); }
  std::size_t index(const glm::ivec3& c) const { return (std::size_t(c.z) * std::size_t(dims_.y) + std::size_t(c.y)) * std::size_t(dims_.x) + std::size_t(c.x); }
  const std::vector<std::uint32_t>& at(const glm::ivec3& c) const { return cells_[index(c)]; }
  glm::ivec3 dims() const { return dims_; }
  // A lower bound of the distance from p to every cell more than r cells (on some axis) from p's clamped cell:
  // on that axis p lies inside its own cell's range or beyond the grid on the near side, so the gap is at
  // least r whole cells.
  float clearance(int r) const { return float(r) * cell_; }

 private:
  std::pair<glm::ivec3, glm::ivec3> cellsOf(std::span<const glm::vec3> positions, const glm::uvec3& tri) const {
    const glm::vec3 a = positions[tri.x], b = positions[tri.y], c = positions[tri.z];
    return {cellOf(glm::min(a, glm::min(b, c))), cellOf(glm::max(a, glm::max(b, c)))};
  }
  std::uint64_t entries(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles) const {
    std::uint64_t n = 0;
    for (const glm::uvec3& t : triangles) {
      const auto [from, to] = cellsOf(positions, t);
      const glm::ivec3 span = to - from + 1;
      n += std::uint64_t(span.x) * std::uint64_t(span.y) * std::uint64_t(span.z);
      if (n > kMaxEntries) return n;
    }
    return n;
  }

  glm::vec3 lo_{std::numeric_limits<float>::max()}, hi_{std::numeric_limits<float>::lowest()};
  float cell_ = 1.0f;
  glm::ivec3 dims_{1};
  std::vector<std::vector<std::uint32_t>> cells_;
};

struct Nearest {
  std::uint32_t triangle = 0;
  float distance = std::numeric_limits<float>::max();
};

// Shells of cells around p's cell, until the nearest triangle found is nearer than any unsearched cell.
Nearest nearestTriangle(const glm::vec3& p, const TriangleGrid& grid, std::span<const glm::vec3> pos, std::span<const glm::uvec3> tris) {
  Nearest best;
  const glm::ivec3 c = grid.cellOf(p), dims = grid.dims();
  for (int r = 0;; ++r) {
    const glm::ivec3 from = glm::max(c - r, glm::ivec3(0)), to = glm::min(c + r, dims - 1);
    for (int z = from.z; z <= to.z; ++z)
      for (int y = from.y; y <= to.y; ++y)
        for (int x = from.x; x <= to.x; ++x) {
          if (std::max({std::abs(x - c.x), std::abs(y - c.y), std::abs(z - c.z)}) != r) continue;  // this shell only
          for (std::uint32_t t : grid.at({x, y, z})) {
            const glm::uvec3 tri = tris[t];
            const float d = glm::distance(p, closestPointOnTriangle(p, pos[tri.x], pos[tri.y], pos[tri.z]));
            if (d < best.distance || (d == best.distance && t < best.triangle)) best = {t, d};
          }
        }
    const bool whole = from == glm::ivec3(0) && to == dims - 1;
    if (whole || best.distance <= grid.clearance(r)) return best;
  }
}

glm::vec3 unitNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 n = glm::cross(b - a, c - a);
  const float len = glm::length(n);
  return len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

RootBinding bindTo(const glm::vec3& p, std::uint32_t t, float distance, std::span<const glm::vec3> pos, std::span<const glm::uvec3> tris) {
  const glm::vec3 a = pos[tris[t].x], b = pos[tris[t].y], c = pos[tris[t].z];
  const glm::vec3 n = unitNormal(a, b, c);
  const float offset = glm::dot(p - a, n);
  const glm::vec3 q = p - offset * n;  // on the plane
  // Barycentrics of q from the sub-triangle areas, signed by the normal.
  const float area = glm::dot(glm::cross(b - a, c - a), n);
  const float wb = glm::dot(glm::cross(q - a, c - a), n) / area, wc = glm::dot(glm::cross(b - a, q - a), n) / area;
  return {t, {wb, wc}, offset, distance};
}
}  // namespace

RootBindings bindRoots(std::span<const glm::vec3> roots, std::span<const glm::vec3> positions,
                       std::span<const glm::uvec3> triangles, float farDistance) {
  if (triangles.empty()) throw Error("binding roots: the mesh has no triangles");
  const TriangleGrid grid(positions, triangles);
  RootBindings out;
  out.farDistance = farDistance;
  out.roots.reserve(roots.size());
  double sum = 0.0;
  for (const glm::vec3& p : roots) {
    const Nearest n = nearestTriangle(p, grid, positions, triangles);
    out.roots.push_back(bindTo(p, n.triangle, n.distance, positions, triangles));
    out.farRoots += n.distance > farDistance ? 1u : 0u;
    out.maxDistance = std::max(out.maxDistance, n.distance);
    sum += n.distance;
  }
  out.meanDistance = roots.empty() ? 0.0f : float(sum / double(roots.size()));
  return out;
}

glm::vec3 boundRootPosition(const RootBinding& binding, std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles) {
  const glm::uvec3 t = triangles[binding.triangle];
  const glm::vec3 a = positions[t.x], b = positions[t.y], c = positions[t.z];
  const glm::vec2 w = binding.barycentric;
  return a * (1.0f - w.x - w.y) + b * w.x + c * w.y + binding.offset * unitNormal(a, b, c);
}

std::vector<gpu::SkinWeights> boundRootSkin(const RootBindings& bindings, const CharacterMesh& mesh) {
  if (!mesh.skinned()) throw Error(mesh.source + ": the mesh has no skin to bind roots to");
  std::vector<gpu::SkinWeights> out;
  out.reserve(bindings.roots.size());
  for (const RootBinding& r : bindings.roots) {
    glm::vec3 b(1.0f - r.barycentric.x - r.barycentric.y, r.barycentric.x, r.barycentric.y);
    b = glm::max(b, glm::vec3(0.0f));
    b /= std::max(b.x + b.y + b.z, 1e-30f);
    std::map<std::uint32_t, float> byJoint;
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[r.triangle][k];
      for (int s = 0; s < 4; ++s) byJoint[mesh.joints[v][s]] += b[k] * mesh.weights[v][s];
    }
    std::vector<std::pair<float, std::uint32_t>> ranked;
    for (const auto& [joint, weight] : byJoint) ranked.emplace_back(-weight, joint);
    std::sort(ranked.begin(), ranked.end());  // heaviest first, ties by joint
    gpu::SkinWeights w{};
    float sum = 0.0f;
    for (std::size_t s = 0; s < std::min<std::size_t>(4, ranked.size()); ++s)
      w.bones[int(s)] = ranked[s].second, w.weights[int(s)] = -ranked[s].first, sum += -ranked[s].first;
    w.weights /= std::max(sum, 1e-30f);
    out.push_back(w);
  }
  return out;
}
}  // namespace hp
