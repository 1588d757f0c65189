#pragma once
// Contract: meshes the zero level set of an SdfGrid by marching tetrahedra: every grid cell is split
// into the six tetrahedra of the Kuhn triangulation (all around the cell's main diagonal, so
// neighbouring cells split their shared face the same way), and every tetrahedron the surface crosses
// gives one or two triangles with vertices on its edges. Vertices are shared between tetrahedra (one
// per crossed grid edge), so the mesh is closed and manifold with no ambiguous cases; each vertex is
// the zero of `field` on its edge (regula falsi; the grid's nodes must be samples of `field`).
// Triangles are counter-clockwise seen from outside (the positive side); normals are the field's
// normalized gradient. A surface that reaches the grid's boundary throws hp::Error. Deterministic.
#include "engine/hair/hair_asset.h"
#include "engine/hair/sdf_grid.h"

namespace hp {
HeadMesh meshZeroLevel(const SdfGrid& grid, const DistanceFunction& field);
}  // namespace hp
