#include "engine/core/hair/marching_cubes_table.h"

#include <algorithm>
#include <vector>

namespace hp {
namespace {
// Edge e = axis * 4 + k: k holds the corner's bits on the two other axes, in cyclic order after the axis.
std::uint32_t edgeBetween(std::uint32_t u, std::uint32_t v) {
  const std::uint32_t lower = u & v, differ = u ^ v;
  const std::uint32_t axis = differ == 1u ? 0u : differ == 2u ? 1u : 2u;
  const std::uint32_t b = (axis + 1) % 3, c = (axis + 2) % 3;
  return axis * 4 + (((lower >> b) & 1u) | (((lower >> c) & 1u) << 1));
}

// A face's corners counter-clockwise seen from outside the cube: on the face axis = side, around the
// two other axes (b, c) in cyclic order, whose cross product is +axis; reversed on the lower side.
std::array<std::uint32_t, 4> faceCorners(std::uint32_t axis, std::uint32_t side) {
  const std::uint32_t b = (axis + 1) % 3, c = (axis + 2) % 3, base = side << axis;
  std::array<std::uint32_t, 4> q{base, base | (1u << b), base | (1u << b) | (1u << c), base | (1u << c)};
  if (side == 0) std::swap(q[1], q[3]);
  return q;
}

// next[e]: the crossed edge that follows crossed edge e around its loop. On each face a segment runs
// from an edge where the walk (counter-clockwise from outside) leaves the inside corners back to the
// edge where it entered that chain of inside corners: the chain is on the segment's left.
std::array<int, 12> segments(std::uint32_t inside) {
  std::array<int, 12> next;
  next.fill(-1);
  auto in = [&](std::uint32_t corner) { return (inside >> corner) & 1u; };
  for (std::uint32_t axis = 0; axis < 3; ++axis)
    for (std::uint32_t side = 0; side < 2; ++side) {
      const auto q = faceCorners(axis, side);
      for (int i = 0; i < 4; ++i) {
        if (!in(q[i]) || in(q[(i + 1) % 4])) continue;
        int j = i;
        while (in(q[(j + 3) % 4])) j = (j + 3) % 4;
        next[edgeBetween(q[i], q[(i + 1) % 4])] = int(edgeBetween(q[(j + 3) % 4], q[j]));
      }
    }
  return next;
}

// Bit f of the result: edge e lies on face f = axis * 2 + side.
std::uint32_t edgeFaces(std::uint32_t e) {
  const std::uint32_t axis = e / 4, corner = edgeCorner(e);
  std::uint32_t faces = 0;
  for (std::uint32_t other = 0; other < 3; ++other)
    if (other != axis) faces |= 1u << (other * 2 + ((corner >> other) & 1u));
  return faces;
}

using Triangles = std::vector<std::array<std::uint8_t, 3>>;

// Alternate ears from polygon[0]: (p0 p1 p2), (p2 p3 p4), ... then the same on the kept p0, p2, ...
Triangles alternateEars(std::vector<std::uint8_t> polygon) {
  Triangles out;
  while (polygon.size() >= 3) {
    std::vector<std::uint8_t> kept;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i + 1 < n; i += 2) {
      out.push_back({polygon[i], polygon[i + 1], polygon[(i + 2) % n]});
      kept.push_back(polygon[i]);
    }
    if (n % 2 == 1) kept.push_back(polygon[n - 1]);
    polygon = std::move(kept);
  }
  return out;
}

Triangles fan(const std::vector<std::uint8_t>& polygon) {
  Triangles out;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) out.push_back({polygon[0], polygon[i], polygon[i + 1]});
  return out;
}

// A diagonal (an edge inside the polygon) must not join two vertices on one cube face: the cell across
// that face (an ambiguous one, cut in two segments) could join the same two vertices, and the edge
// would then have four triangles.
bool diagonalsStayOffFaces(const Triangles& triangles, const std::vector<std::uint8_t>& polygon) {
  const std::size_t n = polygon.size();
  auto boundary = [&](std::uint8_t a, std::uint8_t b) {
    for (std::size_t i = 0; i < n; ++i)
      if ((polygon[i] == a && polygon[(i + 1) % n] == b) || (polygon[i] == b && polygon[(i + 1) % n] == a)) return true;
    return false;
  };
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (!boundary(t[k], t[(k + 1) % 3]) && (edgeFaces(t[k]) & edgeFaces(t[(k + 1) % 3]))) return false;
  return true;
}

// The first of: alternate ears, then fans, from each starting vertex in turn, whose diagonals stay
// off the faces. (Every loop of the 256 cases has one: MarchingCubes.EveryCaseUsesExactlyItsCrossedEdges would see the hole.)
void triangulate(const std::vector<std::uint8_t>& polygon, MarchingCase& out) {
  Triangles chosen;
  for (int kind = 0; kind < 2 && chosen.empty(); ++kind)
    for (std::size_t start = 0; start < polygon.size() && chosen.empty(); ++start) {
      std::vector<std::uint8_t> rotated(polygon.begin() + std::ptrdiff_t(start), polygon.end());
      rotated.insert(rotated.end(), polygon.begin(), polygon.begin() + std::ptrdiff_t(start));
      Triangles t = kind == 0 ? alternateEars(rotated) : fan(rotated);
      if (diagonalsStayOffFaces(t, polygon)) chosen = std::move(t);
    }
  if (chosen.empty()) return;  // leaves a hole: the table test fails
  for (const auto& t : chosen) {
    std::copy(t.begin(), t.end(), out.edges.begin() + 3 * std::ptrdiff_t(out.triangleCount));
    ++out.triangleCount;
  }
}

// The loops of `next` as polygons, reversed: the segments circle the inside corners counter-clockwise
// seen from outside the cube, i.e. seen from the negative side of the surface.
MarchingCase build(std::uint32_t inside) {
  const std::array<int, 12> next = segments(inside);
  MarchingCase out;
  std::array<bool, 12> used{};
  for (std::uint32_t start = 0; start < 12; ++start) {
    if (next[start] < 0 || used[start]) continue;
    std::vector<std::uint8_t> loop;
    for (int e = int(start); !used[std::size_t(e)]; e = next[std::size_t(e)]) {
      used[std::size_t(e)] = true;
      loop.insert(loop.begin(), std::uint8_t(e));
    }
    triangulate(loop, out);
  }
  return out;
}

std::array<MarchingCase, 256> buildTable() {
  std::array<MarchingCase, 256> table;
  for (std::uint32_t c = 0; c < 256; ++c) table[c] = build(c);
  return table;
}
}  // namespace

const std::array<MarchingCase, 256>& marchingCases() {
  static const std::array<MarchingCase, 256> table = buildTable();
  return table;
}
}  // namespace hp
