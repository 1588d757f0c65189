#pragma once
// Contract: the marching-cubes case table, generated once (not typed in) from one rule, so it is
// consistent by construction. Cube corner n = x + 2y + 4z; a case is the set of inside corners (bit n:
// corner n has a negative value). Edge e joins corner edgeCorner(e) to edgeCorner(e) + axis e / 4.
// On each cube face the crossed edges are joined by segments that cut off the face's inside corners,
// chains of adjacent inside corners together; a face with two diagonal inside corners (ambiguous)
// therefore always separates them. The decision depends only on the face's four signs, so the two
// cells that share a face cut it the same way. Each closed loop of segments is one polygon,
// triangulated by cutting alternate ears (fewer slivers than a fan), or else by a fan, from the first
// start whose inner diagonals never join two vertices on one cube face: the cell across an ambiguous
// face could join the same two, and the edge would have four triangles. With both rules meshes are
// closed and manifold. Every triangle is counter-clockwise seen from outside (the positive side).
// Pure and deterministic.
#include <array>
#include <cstdint>

namespace hp {
struct MarchingCase {
  std::uint8_t triangleCount = 0;
  std::array<std::uint8_t, 36> edges{};  // triangle t: edges[3t], edges[3t + 1], edges[3t + 2]
};

// Edge e in [0, 12): axis e / 4 (0 x, 1 y, 2 z), from the corner edgeCorner(e), whose bits on the two
// other axes (in cyclic order after the axis) are the bits of e % 4; its bit for the axis is 0.
constexpr std::uint32_t edgeAxis(std::uint32_t e) { return e / 4; }
constexpr std::uint32_t edgeCorner(std::uint32_t e) {
  return ((e & 1u) << ((e / 4 + 1) % 3)) | (((e >> 1) & 1u) << ((e / 4 + 2) % 3));
}

// The table: entry c holds the triangles of the case whose inside corners are the set bits of c.
const std::array<MarchingCase, 256>& marchingCases();
inline const MarchingCase& marchingCase(std::uint32_t inside) { return marchingCases()[inside & 255u]; }
}  // namespace hp
