#pragma once
// Contract: resamples a polyline to `particles` points whose arc-length positions follow the growth
// law (geometricArcPositions with `ratio`): root and tip are kept exactly and the spacing increases
// from root to tip. New points lie on the input polyline (linear interpolation by arc length), so
// the result's length is the input's up to the chords cut across curvature.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp {
float polylineLength(std::span<const glm::vec3> points);

// Writes `particles` points to out. A zero-length polyline gives `particles` copies of its root.
void resamplePolyline(std::span<const glm::vec3> points, std::uint32_t particles, float ratio,
                      std::span<glm::vec3> out);
}  // namespace hp
