#include "engine/core/hair/hairline_distance.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <tuple>
#include <utility>

namespace hp {
namespace {
using Edge = std::pair<std::uint32_t, std::uint32_t>;  // guide indices, smaller first

Edge edgeOf(std::uint32_t a, std::uint32_t b) { return a < b ? Edge{a, b} : Edge{b, a}; }

bool degenerate(const glm::uvec3& t) { return t.x == t.y || t.y == t.z || t.x == t.z; }

// The triangles using each edge of the non-degenerate triangles.
std::map<Edge, std::vector<std::uint32_t>> edgeUsers(std::span<const glm::uvec3> triangles) {
  std::map<Edge, std::vector<std::uint32_t>> users;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const glm::uvec3& v = triangles[t];
    if (degenerate(v)) continue;
    for (const Edge& e : {edgeOf(v.x, v.y), edgeOf(v.y, v.z), edgeOf(v.z, v.x)}) users[e].push_back(t);
  }
  return users;
}

// The roots bucketed in cubes of side `cell` from their bounding box's corner, to find the roots near a
// point. Cell coordinates are clamped to [-1, kMaxCells] (a hostile file's roots may lie 1e30 apart), so
// far cells merge: slower there, never wrong, since every candidate's distance is checked.
class RootGrid {
 public:
  static constexpr float kMaxCells = 1 << 20;
  static constexpr int kMaxReach = 2;  // cells searched each way: radii past 2 cells are searched to 2 cells
  RootGrid(std::span<const glm::vec3> roots, float cell) : roots_(roots), cell_(cell) {
    for (const glm::vec3& p : roots) low_ = glm::min(low_, p);
    for (std::uint32_t i = 0; i < roots.size(); ++i) buckets_[keyOf(roots[i])].push_back(i);
  }
  // Whether a root lies within `radius` of p (within min(radius, kMaxReach cells) where radius is longer).
  bool anyWithin(const glm::vec3& p, float radius) const {
    const auto [x, y, z] = keyOf(p);
    const int reach = radius < cell_ ? 1 : radius < 2.0f * cell_ ? 2 : kMaxReach;
    for (int dz = -reach; dz <= reach; ++dz)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const auto it = buckets_.find({x + dx, y + dy, z + dz});
          if (it == buckets_.end()) continue;
          for (std::uint32_t i : it->second)
            if (glm::length(roots_[i] - p) < radius) return true;
        }
    return false;
  }

 private:
  using Key = std::tuple<int, int, int>;
  Key keyOf(const glm::vec3& p) const {
    glm::vec3 k = glm::floor((p - low_) / cell_);
    for (int c = 0; c < 3; ++c) k[c] = k[c] >= -1.0f ? std::min(k[c], kMaxCells) : -1.0f;  // NaN: -1
    return {int(k.x), int(k.y), int(k.z)};
  }
  std::span<const glm::vec3> roots_;
  float cell_;
  glm::vec3 low_{std::numeric_limits<float>::max()};
  std::map<Key, std::vector<std::uint32_t>> buckets_;
};

// A boundary edge is the hairline when no root lies beyond it: probed one edge length out from its
// midpoint, in its triangle's plane, away from the triangle. A gap inside the hair (a parting left open,
// triangles dropped as too long) has roots on its far side within about that.
bool onTheHairline(std::span<const glm::vec3> roots, const RootGrid& grid, const glm::uvec3& triangle, const Edge& e) {
  const glm::vec3 a = roots[e.first], b = roots[e.second];
  const std::uint32_t other = triangle.x != e.first && triangle.x != e.second   ? triangle.x
                              : triangle.y != e.first && triangle.y != e.second ? triangle.y
                                                                                : triangle.z;
  const glm::vec3 mid = 0.5f * (a + b), along = b - a;
  const float length = glm::length(along);
  glm::vec3 out = mid - roots[other];
  out -= along * (glm::dot(out, along) / std::max(glm::dot(along, along), 1e-30f));
  if (!(length > 0.0f) || !(glm::length(out) > 0.0f)) return true;  // a sliver: count it as the rim
  return !grid.anyWithin(mid + glm::normalize(out) * length, length);
}
}  // namespace

std::vector<float> hairlineDistances(std::span<const glm::vec3> roots, std::span<const glm::uvec3> triangles) {
  std::vector<glm::vec3> centroid(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    centroid[t] = (roots[triangles[t].x] + roots[triangles[t].y] + roots[triangles[t].z]) / 3.0f;
  const auto users = edgeUsers(triangles);
  // The grid's cell: the boundary edges' median length (robust to an outlier root), so a probe looks at
  // 27 cells for most edges and the cells hold a few roots each.
  std::vector<float> lengths;
  for (const auto& [edge, ts] : users)
    if (ts.size() == 1) lengths.push_back(glm::length(roots[edge.first] - roots[edge.second]));
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const float median = lengths.empty() ? 1.0f : lengths[lengths.size() / 2];
  const RootGrid grid(roots, median > 1e-30f && median < 1e30f ? median : 1.0f);
  std::vector<float> distance(triangles.size(), kNoHairline);
  std::vector<std::vector<std::uint32_t>> neighbours(triangles.size());
  for (const auto& [edge, ts] : users) {
    if (ts.size() == 1 && onTheHairline(roots, grid, triangles[ts[0]], edge)) {
      // The triangle's distance to the edge's midpoint.
      const glm::vec3 mid = 0.5f * (roots[edge.first] + roots[edge.second]);
      distance[ts[0]] = std::min(distance[ts[0]], glm::length(centroid[ts[0]] - mid));
    }
    for (std::uint32_t a : ts)
      for (std::uint32_t b : ts)
        if (a != b) neighbours[a].push_back(b);
  }
  // Dijkstra from every hairline triangle at once.
  using Item = std::pair<float, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  for (std::uint32_t t = 0; t < distance.size(); ++t)
    if (distance[t] < kNoHairline) open.emplace(distance[t], t);
  while (!open.empty()) {
    const auto [d, t] = open.top();
    open.pop();
    if (d > distance[t]) continue;  // a shorter path got there first
    for (std::uint32_t n : neighbours[t]) {
      const float through = d + glm::length(centroid[n] - centroid[t]);
      if (through < distance[n]) open.emplace(distance[n] = through, n);
    }
  }
  return distance;
}
}  // namespace hp
