#pragma once
// Contract: finds the scalp triangles whose guides part around the head. A render strand is a blend of its
// triangle's three guides; where they fall to opposite sides of the head (a parting, a whorl), the blend runs
// through it. The head is the body the hair collides with: sphere colliders and a distance grid (a character
// mesh or scene collider meshes), either may be absent. A triangle is parted when, at some particle past the
// root, the blend at its centroid or at an edge's midpoint lies deeper inside the body than the deepest of its
// guides' own particles there (or than the body's surface, if none is inside) by more than `marginLength`.
// Blends of guides that lie side by side dip under the surface only by the sagitta of their spread (a few
// millimetres on a head); a parted triangle's blend passes centimetres inside. Without a body nothing is
// parted. A triangle naming a guide outside `guides` is kept (the interpolation topology refuses it).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/hair/collider.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp {
// The margin as a fraction of the head's radius.
inline constexpr float kPartedMargin = 0.1f;

// The union of the spheres and the grid's inside.
struct CollisionBody {
  std::span<const SphereCollider> spheres;
  const SdfGrid* grid = nullptr;  // null: spheres only

  bool empty() const { return spheres.empty() && (grid == nullptr || grid->empty()); }
  // How far p lies inside (negative: outside). A NaN p reads as outside (imports refuse non-finite points).
  float depth(const glm::vec3& p) const;
};

struct PartedTriangles {
  std::vector<glm::uvec3> kept;  // in their given order
  std::uint32_t dropped = 0;
};

PartedTriangles dropPartedTriangles(const GuideSet& guides, std::span<const glm::uvec3> triangles,
                                    const CollisionBody& body, float marginLength);
}  // namespace hp
