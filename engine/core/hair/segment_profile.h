#pragma once
// Contract: the particle spacing law of paper §1, and polylines put on it. A strand of total length L
// split into n segments whose lengths grow geometrically from root to tip: l_k = l_0 * ratio^k,
// sum l_k = L. ratio = 1 gives even spacing; ratio > 1 puts particles close together at the root (where
// hair bends most visibly near the scalp) and far apart at the tip, so long hair needs few particles.
// resamplePolyline moves an imported polyline onto the law: root and tip are kept exactly, new points lie
// on the input polyline (linear interpolation by arc length), so the result's length is the input's up
// to the chords cut across curvature.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp {
// Throws hp::Error if segments == 0, total is not finite and positive, or ratio is not in [1, 4].
std::vector<float> geometricSegmentLengths(float total, float ratio, std::uint32_t segments);
// Cumulative arc length at each of the segments + 1 particles (0 at the root, total at the tip).
std::vector<float> geometricArcPositions(float total, float ratio, std::uint32_t segments);

float polylineLength(std::span<const glm::vec3> points);
// Writes `particles` points to out, at geometricArcPositions(length, ratio, particles - 1). A zero-length
// polyline gives `particles` copies of its root.
void resamplePolyline(std::span<const glm::vec3> points, std::uint32_t particles, float ratio,
                      std::span<glm::vec3> out);
}  // namespace hp
