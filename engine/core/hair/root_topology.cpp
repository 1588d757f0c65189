#include "engine/core/hair/root_topology.h"

#include <algorithm>

#include "engine/core/hair/convex_hull.h"

namespace hp {
namespace {
double longestEdge(const std::vector<glm::dvec3>& dirs, const glm::uvec3& t) {
  return std::max({glm::length(dirs[t.x] - dirs[t.y]), glm::length(dirs[t.y] - dirs[t.z]),
                   glm::length(dirs[t.z] - dirs[t.x])});
}

std::vector<glm::dvec3> projectToUnitSphere(std::span<const glm::vec3> roots, const glm::vec3& center) {
  std::vector<glm::dvec3> dirs(roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    glm::dvec3 d = glm::dvec3(roots[i]) - glm::dvec3(center);
    double len = glm::length(d);
    dirs[i] = len > 0.0 ? d / len : glm::dvec3(0.0);  // a root at the center sinks inside the hull
  }
  return dirs;
}

double facing(const std::vector<glm::dvec3>& dirs, const glm::uvec3& t) {
  glm::dvec3 n = glm::cross(dirs[t.y] - dirs[t.x], dirs[t.z] - dirs[t.x]);
  glm::dvec3 c = dirs[t.x] + dirs[t.y] + dirs[t.z];
  double ln = glm::length(n), lc = glm::length(c);
  return (ln > 0.0 && lc > 0.0) ? glm::dot(n, c) / (ln * lc) : -1.0;
}
}  // namespace

RootTriangulation triangulateRoots(std::span<const glm::vec3> roots, const glm::vec3& center,
                                   const RootTriangulationOptions& options) {
  std::vector<glm::dvec3> dirs = projectToUnitSphere(roots, center);
  std::vector<glm::uvec3> hull = convexHull(dirs);
  RootTriangulation out;
  std::vector<glm::uvec3> facingOut;
  for (const auto& t : hull) {
    if (facing(dirs, t) >= options.minFacing) facingOut.push_back(t);
    else ++out.droppedFacingAway;
  }
  if (facingOut.empty()) return out;
  std::vector<double> edges(facingOut.size());
  for (std::size_t i = 0; i < facingOut.size(); ++i) edges[i] = longestEdge(dirs, facingOut[i]);
  std::vector<double> sorted = edges;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  double limit = options.maxEdgeFactor * sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < facingOut.size(); ++i) {
    if (edges[i] <= limit) out.triangles.push_back(facingOut[i]);
    else ++out.droppedLarge;
  }
  return out;
}
}  // namespace hp
