#include "engine/core/hair/narrow_band.h"

#include <algorithm>
#include <array>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/hair/parallel_for.h"

namespace hp {
namespace {
constexpr std::uint32_t kTopCells = 32;  // cells per side of the coarsest boxes
constexpr float kPad = 0.1f;             // cells added around every box (the mesher's gradient probes)

struct FarBlock {
  glm::uvec3 cellLo, cellHi;     // its nodes: [cellLo, cellHi] (closed)
  std::array<float, 8> corner;  // exact values, corner n = x + 2y + 4z
};

struct NearBrick {
  glm::uvec3 brick;
  sdf::Program program;
};

// Buffers a thread reuses from brick to brick (no allocation per brick once they have grown).
struct Scratch {
  std::vector<glm::vec3> points;
  std::vector<std::size_t> where;
  std::vector<float> values;
  std::vector<std::uint8_t> done;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

struct Found {
  std::vector<FarBlock> far;
  std::vector<NearBrick> near;
};

class Sampler {
 public:
  Sampler(const sdf::Program& field, SdfGrid& grid, std::uint32_t brickCells, float band)
      : field_(field), g_(grid), B_(brickCells), cells_(grid.dims - 1u), bricks_((cells_ + B_ - 1u) / B_), band_(band) {
    for (int axis = 0; axis < 3; ++axis)
      for (std::uint32_t i = 0; i < grid.dims[axis]; ++i) coord_[axis].push_back(grid.node(i, i, i)[axis]);
  }

  NarrowBandGrid run() {
    const std::uint32_t topBricks = std::max(1u, kTopCells / B_);
    const glm::uvec3 tops = (bricks_ + topBricks - 1u) / topBricks;
    std::vector<Found> found(std::size_t(tops.x) * tops.y * tops.z);
    parallelFor(found.size(), [&](std::size_t t) {
      const glm::uvec3 top(t % tops.x, (t / tops.x) % tops.y, t / (std::size_t(tops.x) * tops.y));
      classify(top * topBricks, glm::min((top + 1u) * topBricks, bricks_), field_, found[t]);
    }, 1);
    collect(found);
    std::vector<std::size_t> exact(brickFar_.size(), 0);
    signs_.assign(brickFar_.size(), 0);
    // Far blocks first, whole (long rows), then the near bricks and the far nodes they share.
    parallelFor(far_.size(), [&](std::size_t f) {
      const FarBlock& block = far_[f];
      fillFar(block, block.cellLo, glm::mix(block.cellHi, cells_ + 1u, glm::equal(block.cellHi, cells_)));
    }, 4);
    parallelFor(brickFar_.size(), [&](std::size_t b) { exact[b] = fillBrick(brickCoords(b), signs_[b]); }, 16);
    NarrowBandGrid out;
    for (std::size_t e : exact) out.exactNodes += e;
    out.band.signs = std::move(signs_);
    out.band.brickCells = B_;
    out.band.bricks = bricks_;
    out.band.nearSlot = std::move(nearSlot_);
    auto programs = std::make_shared<std::vector<sdf::Program>>(std::move(programs_));
    out.band.exact = [programs](std::int32_t slot, const glm::vec3& p) { return (*programs)[std::size_t(slot)](p); };
    out.band.exactMany = [programs](std::int32_t slot, std::span<const glm::vec3> points, std::span<float> values) {
      (*programs)[std::size_t(slot)].evaluate(points, values);
    };
    out.grid = std::move(g_);
    return out;
  }

 private:
  const sdf::Program& field_;
  SdfGrid& g_;
  const std::uint32_t B_;
  const glm::uvec3 cells_, bricks_;
  const float band_;
  std::vector<FarBlock> far_;
  std::vector<sdf::Program> programs_;
  std::vector<std::int32_t> brickFar_, nearSlot_;  // per brick: its far block, or its near slot (else -1)
  std::vector<std::uint8_t> signs_;                // per brick: LevelSetBand::signs
  std::array<std::vector<float>, 3> coord_;        // per axis, the nodes' coordinates (SdfGrid::node's values)

  std::size_t brickIndex(const glm::uvec3& b) const { return (std::size_t(b.z) * bricks_.y + b.y) * bricks_.x + b.x; }
  glm::uvec3 brickCoords(std::size_t i) const {
    return {std::uint32_t(i % bricks_.x), std::uint32_t((i / bricks_.x) % bricks_.y),
            std::uint32_t(i / (std::size_t(bricks_.x) * bricks_.y))};
  }
  glm::vec3 node(const glm::uvec3& n) const { return {coord_[0][n.x], coord_[1][n.y], coord_[2][n.z]}; }

  // Bricks [b0, b1): far as a whole, one near brick, or split in halves along each axis.
  void classify(const glm::uvec3& b0, const glm::uvec3& b1, const sdf::Program& parent, Found& out) const {
    const glm::uvec3 c0 = b0 * B_, c1 = glm::min(b1 * B_, cells_);
    const glm::vec3 pad(kPad * g_.cell);
    sdf::Interval range;
    sdf::Program p = parent.specialise(node(c0) - pad, node(c1) + pad, &range);
    if (range.lo > band_ || range.hi < -band_) {
      FarBlock f{c0, c1, {}};
      std::array<glm::vec3, 8> corners;
      for (std::uint32_t n = 0; n < 8; ++n) corners[n] = node({n & 1u ? c1.x : c0.x, n & 2u ? c1.y : c0.y, n & 4u ? c1.z : c0.z});
      p.evaluate(corners, f.corner);
      out.far.push_back(f);
      return;
    }
    if (b1 - b0 == glm::uvec3(1u)) {
      out.near.push_back({b0, std::move(p)});
      return;
    }
    const glm::uvec3 mid = b0 + (b1 - b0 + 1u) / 2u;
    for (std::uint32_t n = 0; n < 8; ++n) {
      const glm::bvec3 upper(n & 1u, n & 2u, n & 4u);
      const glm::uvec3 lo = glm::mix(b0, mid, upper), hi = glm::mix(mid, b1, upper);
      if (glm::all(glm::lessThan(lo, hi))) classify(lo, hi, p, out);
    }
  }

  // Far blocks and near slots, numbered in the fixed order of the top boxes.
  void collect(std::vector<Found>& found) {
    brickFar_.assign(std::size_t(bricks_.x) * bricks_.y * bricks_.z, -1);
    nearSlot_.assign(brickFar_.size(), -1);
    for (Found& f : found) {
      for (const FarBlock& block : f.far) {
        const glm::uvec3 b0 = block.cellLo / B_, b1 = (block.cellHi + B_ - 1u) / B_;
        for (std::uint32_t z = b0.z; z < b1.z; ++z)
          for (std::uint32_t y = b0.y; y < b1.y; ++y)
            for (std::uint32_t x = b0.x; x < b1.x; ++x) brickFar_[brickIndex({x, y, z})] = std::int32_t(far_.size());
        far_.push_back(block);
      }
      for (NearBrick& n : f.near) {
        nearSlot_[brickIndex(n.brick)] = std::int32_t(programs_.size());
        programs_.push_back(std::move(n.program));
      }
    }
  }

  // Whether a near brick shares a node with brick b's lower faces (the bricks at -x, -y, -z and between).
  bool nearBelow(const glm::uvec3& b) const {
    for (std::uint32_t d = 1; d < 8; ++d) {
      const glm::uvec3 step(d & 1u, (d >> 1) & 1u, (d >> 2) & 1u);
      if (glm::all(glm::greaterThanEqual(b, step)) && nearSlot_[brickIndex(b - step)] >= 0) return true;
    }
    return false;
  }

  // The trilinear blend of the far block's corner values at every node of [lo, hi) (t = the node's
  // fraction of the block per axis); the x blends are computed once per column, not per node.
  void fillFar(const FarBlock& f, const glm::uvec3& lo, const glm::uvec3& hi) {
    constexpr std::uint32_t kMax = kTopCells + 1;  // nodes a far block owns per axis (at most a top box, plus the last node)
    std::array<float, kMax> x00, x10, x01, x11;
    const glm::vec3 span = glm::max(glm::vec3(f.cellHi - f.cellLo), glm::vec3(1.0f));
    const auto& v = f.corner;
    for (std::uint32_t x = lo.x; x < hi.x; ++x) {
      const float t = float(x - f.cellLo.x) / span.x;
      x00[x - lo.x] = glm::mix(v[0], v[1], t), x10[x - lo.x] = glm::mix(v[2], v[3], t);
      x01[x - lo.x] = glm::mix(v[4], v[5], t), x11[x - lo.x] = glm::mix(v[6], v[7], t);
    }
    for (std::uint32_t z = lo.z; z < hi.z; ++z) {
      const float tz = float(z - f.cellLo.z) / span.z;
      for (std::uint32_t y = lo.y; y < hi.y; ++y) {
        const float ty = float(y - f.cellLo.y) / span.y;
        float* row = &g_.values[g_.index(lo.x, y, z)];
        for (std::uint32_t i = 0; i < hi.x - lo.x; ++i)
          row[i] = glm::mix(glm::mix(x00[i], x10[i], ty), glm::mix(x01[i], x11[i], ty), tz);
      }
    }
  }

  // The nodes brick b owns: [b B, (b + 1) B) per axis, the last brick also the grid's last node. A near
  // brick evaluates them all (one batch); in a far one (already blended with its far block) those on
  // its lower faces that a near neighbour shares are evaluated.
  std::size_t fillBrick(const glm::uvec3& b, std::uint8_t& signs) {
    const glm::uvec3 lo = b * B_;
    const glm::uvec3 hi = glm::mix(glm::min((b + 1u) * B_, cells_), cells_ + 1u, glm::equal(b + 1u, bricks_));
    const std::int32_t own = nearSlot_[brickIndex(b)];
    if (own >= 0) return fillNearBrick(programs_[std::size_t(own)], lo, hi, signs);
    const FarBlock& far = far_[std::size_t(brickFar_[brickIndex(b)])];
    signs = far.corner[0] < 0.0f ? LevelSetBand::kSomeInside : LevelSetBand::kSomeOutside;  // sign-definite
    return nearBelow(b) ? fillShared(b, lo, hi) : 0;
  }

  // The nodes of far brick b (owning [lo, hi)) on a face, edge or corner it shares with a near brick
  // below it get the exact field, one batch per such neighbour, with the neighbour's program (every
  // near program gives the field's own value there). Returns how many nodes became exact.
  std::size_t fillShared(const glm::uvec3& b, const glm::uvec3& lo, const glm::uvec3& hi) {
    const glm::uvec3 size = hi - lo;
    auto& [points, where, values, done] = scratch();
    done.assign(std::size_t(size.x) * size.y * size.z, 0);
    std::size_t exact = 0;
    for (std::uint32_t d = 1; d < 8; ++d) {
      const glm::uvec3 step(d & 1u, (d >> 1) & 1u, (d >> 2) & 1u);
      if (!glm::all(glm::greaterThanEqual(b, step))) continue;
      const std::int32_t slot = nearSlot_[brickIndex(b - step)];
      if (slot < 0) continue;
      // Shared with the neighbour: the lower face along each stepped axis, the whole range along the others.
      const glm::uvec3 end = glm::mix(hi, lo + 1u, glm::equal(step, glm::uvec3(1u)));
      points.clear(), where.clear();
      for (std::uint32_t z = lo.z; z < end.z; ++z)
        for (std::uint32_t y = lo.y; y < end.y; ++y)
          for (std::uint32_t x = lo.x; x < end.x; ++x) {
            const std::size_t l = (std::size_t(z - lo.z) * size.y + (y - lo.y)) * size.x + (x - lo.x);
            if (done[l]) continue;
            done[l] = 1;
            points.push_back(node({x, y, z}));
            where.push_back(g_.index(x, y, z));
          }
      values.resize(points.size());
      programs_[std::size_t(slot)].evaluate(points, values);
      for (std::size_t i = 0; i < values.size(); ++i) g_.values[where[i]] = values[i];
      exact += values.size();
    }
    return exact;
  }

  std::size_t fillNearBrick(const sdf::Program& program, const glm::uvec3& lo, const glm::uvec3& hi, std::uint8_t& signs) {
    auto& [points, where, values, done] = scratch();
    points.clear();
    for (std::uint32_t z = lo.z; z < hi.z; ++z)
      for (std::uint32_t y = lo.y; y < hi.y; ++y)
        for (std::uint32_t x = lo.x; x < hi.x; ++x) points.push_back(node({x, y, z}));
    values.resize(points.size());
    program.evaluate(points, values);
    const float* value = values.data();
    for (std::uint32_t z = lo.z; z < hi.z; ++z)
      for (std::uint32_t y = lo.y; y < hi.y; ++y) {
        float* row = &g_.values[g_.index(lo.x, y, z)];
        for (std::uint32_t x = 0; x < hi.x - lo.x; ++x, ++value) {
          row[x] = *value;
          signs |= *value < 0.0f ? LevelSetBand::kSomeInside : LevelSetBand::kSomeOutside;
        }
      }
    return values.size();
  }
};
}  // namespace

NarrowBandGrid sampleNarrowBand(const sdf::Program& field, const glm::vec3& lo, const glm::vec3& hi, float cell,
                                float band, std::uint32_t brickCells, std::size_t maxNodes) {
  if (!(band > 0.0f)) throw Error("narrow band: the band must be positive");
  if (brickCells < 1 || brickCells > 32) throw Error("narrow band: bricks of 1 to 32 cells");
  SdfGrid grid = gridCovering(lo, hi, cell, maxNodes);
  return Sampler(field, grid, brickCells, band).run();
}
}  // namespace hp
