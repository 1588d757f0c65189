#include "engine/core/hair/triangle_bvh.h"

#include <algorithm>
#include <string>

#include "engine/core/error.h"

namespace hp {
namespace {
constexpr std::uint32_t kLeafTriangles = 4;
constexpr std::uint32_t kMaxDepth = 33;  // the median split halves every level: 32 levels hold 2^32 triangles

// The ray's entry distance into the box, or tMax when it misses it within (tMin, tMax).
float boxEntry(const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& origin, const glm::vec3& inverse,
               float tMin, float tMax) {
  const glm::vec3 t0 = (lo - origin) * inverse, t1 = (hi - origin) * inverse;
  const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
  const float enter = std::max({near.x, near.y, near.z, tMin});
  const float leave = std::min({far.x, far.y, far.z, tMax});
  return enter <= leave ? enter : tMax;
}
}  // namespace

TriangleBvh::TriangleBvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices) {
  if (indices.size() % 3 != 0) throw Error("triangle list: the index count is not a multiple of 3");
  const std::size_t count = indices.size() / 3;
  triangles_.reserve(count);
  std::vector<glm::vec3> centroids;
  centroids.reserve(count);
  for (std::size_t t = 0; t < count; ++t) {
    for (int k = 0; k < 3; ++k)
      if (indices[3 * t + k] >= positions.size())
        throw Error("triangle list: index " + std::to_string(indices[3 * t + k]) + " is out of range");
    const glm::vec3 &a = positions[indices[3 * t]], &b = positions[indices[3 * t + 1]], &c = positions[indices[3 * t + 2]];
    triangles_.push_back({a, b - a, c - a});
    centroids.push_back((a + b + c) / 3.0f);
  }
  order_.resize(count);
  for (std::uint32_t i = 0; i < count; ++i) order_[i] = i;
  nodes_.reserve(2 * count / kLeafTriangles + 1);
  if (count == 0) return;
  build(0, static_cast<std::uint32_t>(count), centroids);
  // The triangles in leaf order: a leaf's are contiguous in memory (order_ keeps their indices).
  std::vector<Triangle> sorted(count);
  for (std::size_t i = 0; i < count; ++i) sorted[i] = triangles_[order_[i]];
  triangles_.swap(sorted);
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count, std::span<const glm::vec3> centroids) {
  const std::uint32_t index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  glm::vec3 lo(INFINITY), hi(-INFINITY), clo(INFINITY), chi(-INFINITY);
  for (std::uint32_t i = first; i < first + count; ++i) {
    const Triangle& t = triangles_[order_[i]];  // (not yet in leaf order while building)
    for (const glm::vec3& p : {t.a, t.a + t.ab, t.a + t.ac}) lo = glm::min(lo, p), hi = glm::max(hi, p);
    clo = glm::min(clo, centroids[order_[i]]);
    chi = glm::max(chi, centroids[order_[i]]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  const glm::vec3 extent = chi - clo;
  if (count <= kLeafTriangles || !(glm::max(extent.x, glm::max(extent.y, extent.z)) > 0.0f)) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const std::uint32_t half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                   [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
  build(first, half, centroids);
  const std::uint32_t second = build(first + half, count - half, centroids);
  nodes_[index].first = second;
  return index;
}

std::optional<TriangleBvh::Hit> TriangleBvh::closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMin,
                                                        float tMax) const {
  if (nodes_.empty()) return std::nullopt;
  const glm::vec3 inverse = 1.0f / dir;  // infinities on axis-parallel rays: the slab test handles them
  std::optional<Hit> best;
  struct Pending {
    std::uint32_t node;
    float entry;  // where the ray enters its box
  };
  Pending stack[2 * kMaxDepth + 2];
  std::uint32_t top = 0;
  const float rootEntry = boxEntry(nodes_[0].lo, nodes_[0].hi, origin, inverse, tMin, tMax);
  if (rootEntry < tMax) stack[top++] = {0, rootEntry};
  while (top > 0) {
    const Pending pending = stack[--top];
    if (pending.entry >= tMax) continue;  // a nearer hit was found since it was pushed
    const Node& node = nodes_[pending.node];
    if (node.count == 0) {
      const std::uint32_t a = pending.node + 1, b = node.first;
      const float ea = boxEntry(nodes_[a].lo, nodes_[a].hi, origin, inverse, tMin, tMax);
      const float eb = boxEntry(nodes_[b].lo, nodes_[b].hi, origin, inverse, tMin, tMax);
      // The farther child first, so the nearer one is popped next; a child the ray misses is not pushed.
      const Pending nearer = ea <= eb ? Pending{a, ea} : Pending{b, eb}, farther = ea <= eb ? Pending{b, eb} : Pending{a, ea};
      if (farther.entry < tMax) stack[top++] = farther;
      if (nearer.entry < tMax) stack[top++] = nearer;
      continue;
    }
    for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
      const Triangle& tri = triangles_[i];
      const glm::vec3 p = glm::cross(dir, tri.ac);
      const float det = glm::dot(tri.ab, p);
      if (std::abs(det) < 1e-20f) continue;
      const float inv = 1.0f / det;
      const glm::vec3 s = origin - tri.a;
      const float u = glm::dot(s, p) * inv;
      if (u < 0.0f || u > 1.0f) continue;
      const glm::vec3 q = glm::cross(s, tri.ab);
      const float v = glm::dot(dir, q) * inv;
      if (v < 0.0f || u + v > 1.0f) continue;
      const float t = glm::dot(tri.ac, q) * inv;
      if (t <= tMin || t >= tMax) continue;
      tMax = t;
      best = Hit{order_[i], t, u, v, det > 0.0f};  // det = -dot(dir, ab x ac)
    }
  }
  return best;
}
}  // namespace hp
