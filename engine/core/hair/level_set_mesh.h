#pragma once
// Contract: meshes the zero level set of an SdfGrid by marching cubes (marching_cubes_table.h: a
// table generated from one face rule, so cells that share a face cut it the same way, ambiguous faces
// included). Every crossed grid edge holds one vertex, shared by the cells around it, so the mesh is
// closed and manifold; each vertex is the zero of the exact field on its edge (regula falsi; the
// grid's nodes must be samples of it). Triangles are counter-clockwise seen from outside (the
// positive side); normals are the field's normalized gradient. A surface that reaches the grid's
// boundary throws hp::Error.
// Only the cells of "near" bricks are visited (LevelSetBand): bricks of cubes of cells in which the
// grid's sign is known to be constant are skipped. Bricks are meshed on parallelFor's threads and
// joined in brick order, so the mesh is the same for any thread count. Deterministic.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp {
// The grid's cells in bricks of brickCells^3 (the last ones per axis may be partial), x fastest.
struct LevelSetBand {
  std::uint32_t brickCells = 4;  // 1 to 32
  glm::uvec3 bricks{0};
  std::vector<std::int32_t> nearSlot;  // per brick: -1 where the sign is constant in the brick, else its slot
  // Per brick (far ones too), of the nodes it owns ([b, b + 1) brickCells per axis, the last brick also
  // the grid's last node): bit kSomeInside if one is negative, bit kSomeOutside if one is not. Empty: not
  // known. The mesher ORs a near brick's entry with those of its up to 7 upper neighbours (whose nodes
  // close its cells) and skips the brick, unread, when only one bit is set: so every entry must hold
  // at least the signs its nodes have.
  std::vector<std::uint8_t> signs;
  static constexpr std::uint8_t kSomeInside = 1, kSomeOutside = 2;
  // The exact field near slot's brick (its box grown by a tenth of a cell on every side): at one
  // point, and at many (out[i] = exact(slot, points[i])).
  std::function<float(std::int32_t slot, const glm::vec3& p)> exact;
  std::function<void(std::int32_t slot, std::span<const glm::vec3> points, std::span<float> out)> exactMany;

  std::size_t brickIndex(const glm::uvec3& b) const { return (std::size_t(b.z) * bricks.y + b.y) * bricks.x + b.x; }
};

// Every brick near, the exact field = `field` everywhere.
LevelSetBand wholeGridBand(const SdfGrid& grid, const DistanceFunction& field);

// stride > 1 meshes a coarser lattice: every stride-th node of the grid (stride must divide the band's
// brickCells, so every mesh cell lies in one brick), the same exact field on its edges. The mesh's
// resolution is then independent of the grid's (the collider keeps its fine cells).
HeadMesh meshZeroLevel(const SdfGrid& grid, const LevelSetBand& band, std::uint32_t stride = 1);
HeadMesh meshZeroLevel(const SdfGrid& grid, const DistanceFunction& field);
}  // namespace hp
