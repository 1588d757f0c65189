#pragma once
// Contract: finds the scalp triangles whose guides part around the head. A render strand is a blend of its
// triangle's three guides; where they fall to opposite sides of the head (a parting, a whorl), the blend runs
// through it. A triangle is parted when, at some particle past the root, the blend at its centroid or at an
// edge's midpoint lies deeper inside a sphere collider than the deepest of its guides' own particles there
// (or than the sphere's surface, if none is inside) by more than `margin` times the sphere's radius. Blends
// of guides that lie side by side dip under a sphere only by the sagitta of their spread (a few millimetres on
// a head); a parted triangle's blend passes centimetres inside. Without colliders nothing is parted. A
// triangle naming a guide outside `guides` is kept (the interpolation topology refuses it).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/hair/collider.h"
#include "engine/core/hair/guide_set.h"

namespace hp {
inline constexpr float kPartedMargin = 0.1f;

struct PartedTriangles {
  std::vector<glm::uvec3> kept;  // in their given order
  std::uint32_t dropped = 0;
};

PartedTriangles dropPartedTriangles(const GuideSet& guides, std::span<const glm::uvec3> triangles,
                                    std::span<const SphereCollider> colliders, float margin = kPartedMargin);
}  // namespace hp
