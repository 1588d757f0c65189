#pragma once
// Contract: a head mesh with fewer triangles where fewer change nothing a renderer shows, by half-edge
// collapses (Garland & Heckbert's quadric error), cheapest first. A collapse moves one vertex onto a neighbour,
// so the kept vertices are a subset of the input's and each keeps its position, normal and scalp weight
// exactly. A collapse is made only where
// - the moved vertex lies on no uneven input triangle (scalp weights that differ, or vertex normals more than
//   `maxNormalDegrees` apart) and on no open or non-manifold edge: the hairline, the creases and bends (the
//   ears' and nostrils' roots, the lips) and any border keep their triangles;
// - every triangle it reshapes keeps its vertex normals within `maxNormalDegrees` (shading interpolated over a
//   wide triangle stays close to the surface's), does not flip or vanish, and the mesh stays manifold;
// - the sum of squared distances from the kept vertex to the planes of the triangles merged into it stays
//   within maxError^2 (so each of those planes is within maxError);
// and only while more than `targetTriangles` remain. Triangles keep their winding and the input's order;
// vertices are renumbered in the order the triangles first use them. Deterministic. Indices that are not
// whole triangles or name a missing vertex, attributes that do not match the positions, or bounds that are
// negative or not finite throw hp::Error naming them.
#include <cstdint>

#include "engine/core/hair/hair_asset.h"

namespace hp {
struct SimplifyOptions {
  float maxError = 0.0f;              // how far the surface may move, in the mesh's units, >= 0
  float maxNormalDegrees = 10.0f;     // largest angle between a reshaped triangle's vertex normals, [0, 180]
  std::uint32_t targetTriangles = 0;  // stop at this many (0: only the bounds above stop it)
};

HeadMesh simplifyMesh(const HeadMesh& mesh, const SimplifyOptions& options);
}  // namespace hp
