#pragma once
// Contract: a sphere collider in head space (the asset's own space, metres for the default head).
// The simulation keeps every particle's pearl outside every collider (docs/THEORY.md §2.4).
#include <glm/glm.hpp>

namespace hp {
struct SphereCollider {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  bool operator==(const SphereCollider&) const = default;
};
}  // namespace hp

namespace hp {
// A capsule collider in head space: the points within `radius` of the segment a-b (a limb, the neck).
struct CapsuleCollider {
  glm::vec3 a{0.0f};
  glm::vec3 b{0.0f};
  float radius = 0.0f;
  bool operator==(const CapsuleCollider&) const = default;
};
}  // namespace hp
