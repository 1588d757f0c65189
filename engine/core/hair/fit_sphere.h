#pragma once
// Contract: a sphere through a cloud of points (hair roots lie on a roughly spherical scalp). The
// algebraic least-squares fit (|p|^2 = 2 c.p + k) is solved in double around the centroid. When the
// points are (nearly) coplanar or collinear the fit has no meaningful answer; the result is then a
// stand-in sphere below the points (center = centroid - extent * Y, radius = its distance to the
// centroid) with `fitted` false, which still lets the roots be projected and triangulated.
#include <glm/glm.hpp>

#include <span>

#include "engine/core/hair/collider.h"

namespace hp {
struct SphereFit {
  SphereCollider sphere;
  bool fitted = false;  // false: stand-in sphere (degenerate or too few points)
  float rmsError = 0.0f;  // root-mean-square distance of the points to the sphere surface
};

SphereFit fitSphere(std::span<const glm::vec3> points);  // throws hp::Error if points is empty
}  // namespace hp
