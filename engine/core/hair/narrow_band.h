#pragma once
// Contract: a distance program (sdf_program.h) sampled on a grid, exactly only where it matters.
// The grid's cells are cut into bricks of brickCells^3 and boxes of bricks are bounded coarse to fine
// (boxes of 32^3 cells, then halves) by Program::specialise. A box whose bounds stay beyond
// +-band is sign-definite ("far"): its nodes get the trilinear blend of its eight exact corner
// values, which has the field's sign and a magnitude above `band` (a conservative, correctly signed
// distance for collisions). Every other brick is "near": its nodes get the exact field, evaluated by
// the program specialised to the brick (bit-for-bit program(p)). So every node within `band` of the
// zero level holds the exact value and every cell the surface crosses lies in a near brick; the
// returned LevelSetBand lets level_set_mesh visit only those, with their fast programs, and says per
// brick which signs its nodes have (near bricks the surface does not cross are skipped unread).
// Far blocks, then bricks, run on parallelFor's threads; within each pass a node is written by one
// block or brick only (a far node shared with a near brick is rewritten, exactly, in the second pass),
// so the result never depends on the thread count. Deterministic.
#include <cstddef>

#include "engine/core/hair/level_set_mesh.h"
#include "engine/core/hair/sdf_grid.h"
#include "engine/core/hair/sdf_program.h"

namespace hp {
struct NarrowBandGrid {
  SdfGrid grid;
  LevelSetBand band;
  std::size_t exactNodes = 0;  // nodes holding program(node) itself
};

// The grid of gridCovering(lo, hi, cell, maxNodes). band > 0, in the field's units; brickCells in [1, 32].
NarrowBandGrid sampleNarrowBand(const sdf::Program& field, const glm::vec3& lo, const glm::vec3& hi, float cell,
                                float band, std::uint32_t brickCells = 4, std::size_t maxNodes = std::size_t(1) << 24);
}  // namespace hp
