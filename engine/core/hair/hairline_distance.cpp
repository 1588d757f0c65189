#include "engine/core/hair/hairline_distance.h"

#include <cstdint>
#include <functional>
#include <map>
#include <queue>
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
}  // namespace

std::vector<float> hairlineDistances(std::span<const glm::vec3> roots, std::span<const glm::uvec3> triangles) {
  std::vector<glm::vec3> centroid(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    centroid[t] = (roots[triangles[t].x] + roots[triangles[t].y] + roots[triangles[t].z]) / 3.0f;
  const auto users = edgeUsers(triangles);
  std::vector<float> distance(triangles.size(), kNoHairline);
  std::vector<std::vector<std::uint32_t>> neighbours(triangles.size());
  for (const auto& [edge, ts] : users) {
    if (ts.size() == 1) {  // the hairline: the triangle's distance to the edge's midpoint
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
