#pragma once
// Contract: a signed distance field sampled on a regular grid (negative inside), in the asset's
// head space. Values sit on the grid nodes (x fastest, then y, then z); sample() interpolates them
// trilinearly, exactly as the simulation shader does, and outside the box adds the distance to the
// box so the field stays positive and grows away from it. gradient() is the central difference of
// sample() at half a cell: a smooth normal for tools and tests (the simulation pushes along the interpolant's own
// gradient, shaders/sdf_collide.glsl). Built by sampleField (any distance function) or meshSdf (sdf_mesh.h).
#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace hp {
struct SdfGrid {
  glm::vec3 origin{0.0f};  // position of node (0, 0, 0)
  float cell = 0.0f;       // node spacing, same on every axis
  glm::uvec3 dims{0};      // nodes per axis, each >= 2 when not empty
  std::vector<float> values;

  bool empty() const { return values.empty(); }
  std::size_t index(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return (std::size_t(k) * dims.y + j) * dims.x + i;
  }
  float at(std::uint32_t i, std::uint32_t j, std::uint32_t k) const { return values[index(i, j, k)]; }
  glm::vec3 node(std::uint32_t i, std::uint32_t j, std::uint32_t k) const {
    return origin + cell * glm::vec3(float(i), float(j), float(k));
  }
  glm::vec3 upper() const { return node(dims.x - 1, dims.y - 1, dims.z - 1); }
  float sample(const glm::vec3& p) const;
  glm::vec3 gradient(const glm::vec3& p) const;
};

using DistanceFunction = std::function<float(const glm::vec3&)>;

// A grid of `cell` spacing covering [lo, hi] (rounded outward to whole cells, centered), values 0.
// Throws hp::Error when the box is empty or would need more than `maxNodes` nodes.
SdfGrid gridCovering(const glm::vec3& lo, const glm::vec3& hi, float cell, std::size_t maxNodes = std::size_t(1) << 24);

// gridCovering(lo, hi, cell, maxNodes) with each node = f(node).
SdfGrid sampleField(const DistanceFunction& f, const glm::vec3& lo, const glm::vec3& hi, float cell,
                    std::size_t maxNodes = std::size_t(1) << 24);
}  // namespace hp
