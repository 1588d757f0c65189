#pragma once
// Contract: a sphere collider in head space (the asset's own space, metres for the default head).
// The simulation keeps every particle's pearl outside every collider (REFERENCES.md §2).
#include <glm/glm.hpp>

namespace hp {
struct SphereCollider {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  bool operator==(const SphereCollider&) const = default;
};
}  // namespace hp
