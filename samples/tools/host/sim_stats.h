#pragma once
// Contract: measures of a simulated guide state, computed on the host from a readback (outside the
// frame loop): segment length error, clearance to the colliders, NaNs, speed, the hair layer's thickness. Used by
// `hairpipe simulate`, the tests and the benchmark.
#include <glm/glm.hpp>

#include <span>
#include <vector>

#include "engine/core/hair/collider.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp {
// How far the hair stands off the head: the distance field's value at each guide's middle particle
// (particle P / 2, moved into head space by inverse(head)), over the guides with finite positions.
struct LayerThickness {
  double mean = 0.0;
  double p90 = 0.0;  // 90th percentile
  std::size_t guides = 0;
};
LayerThickness hairLayerThickness(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                  const SdfGrid& sdf, const glm::mat4& head);

// How deep the hair is inside a character's mesh: per free particle (moved into head space by
// inverse(head)) its distance to the nearest triangle, negative where it lies behind that triangle's face.
struct MeshPenetration {
  double deepest = 0.0;        // the largest depth inside the mesh (0: none inside)
  double minClearance = 0.0;   // the smallest signed distance (negative: inside)
  std::size_t inside = 0;      // free particles inside
  std::size_t particles = 0;   // free particles with finite positions
};
// `vertices`: the mesh as posed (its rest positions, or a pose's skinMesh).
MeshPenetration meshPenetration(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                std::span<const glm::vec3> vertices, std::span<const glm::uvec3> triangles,
                                const glm::mat4& head);

struct SimStats {
  double maxLengthError = 0.0;        // max over segments of |len - rest| / rest
  double minColliderClearance = 0.0;  // min over particles and colliders of |x - c| - r_c - r_p
  std::size_t nanCount = 0;           // particles with a non-finite coordinate
  double maxSpeed = 0.0;              // max |x - x_prev| / h over free particles
  double kineticEnergy = 0.0;         // sum of 0.5 |v|^2 over free particles (unit mass)
};

// positions/previous: vec4 per particle (w ignored); rest: xyz head-space rest pose, w rest length.
SimStats computeSimStats(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous,
                         std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
                         std::span<const SphereCollider> colliders, const glm::mat4& head, double pearlRadius,
                         double substepSeconds);
}  // namespace hp
