#pragma once
// Contract: a bounding volume hierarchy over a triangle list, built once, answering closest-hit ray
// queries (Moller-Trumbore against each candidate triangle, both faces). Built by splitting the
// triangles at the median centroid along the longest axis of their centroids' box, down to small
// leaves: no surface-area heuristic, which suits meshes of evenly sized triangles (scanned and
// marching-cubes heads) and keeps the build a few sorts. The positions and indices are copied; queries
// are const and may run on several threads at once.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hp {
class TriangleBvh {
 public:
  struct Hit {
    std::uint32_t triangle = 0;  // index into the triangle list (indices / 3)
    float t = 0.0f;              // distance along the (unit) direction
    float u = 0.0f, v = 0.0f;    // barycentrics of the triangle's second and third corners
    bool front = true;           // the ray meets the counter-clockwise side
  };

  // indices: a triangle list into positions (checked: hp::Error on an index out of range).
  TriangleBvh(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices);

  // The nearest hit with t in (tMin, tMax), dir of unit length.
  std::optional<Hit> closestHit(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const;
  std::uint32_t triangleCount() const { return static_cast<std::uint32_t>(triangles_.size()); }

 private:
  struct Node {
    glm::vec3 lo, hi;
    std::uint32_t first = 0;  // leaf: first entry of order_; inner: index of the second child (first = this + 1)
    std::uint32_t count = 0;  // leaf: triangles; 0: inner
  };
  struct Triangle {
    glm::vec3 a, ab, ac;
  };
  std::uint32_t build(std::uint32_t first, std::uint32_t count, std::span<const glm::vec3> centroids);
  std::vector<Triangle> triangles_;   // in leaf order once built
  std::vector<std::uint32_t> order_;  // the triangle index of each entry of triangles_
  std::vector<Node> nodes_;
};
}  // namespace hp
