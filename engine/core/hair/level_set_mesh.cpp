#include "engine/core/hair/level_set_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/illinois_bracket.h"
#include "engine/core/hair/marching_cubes_table.h"
#include "engine/core/hair/parallel_for.h"

namespace hp {
namespace {
// The zero of the field on an edge a-b whose grid values fa, fb differ in sign, to 1 micrometre of
// field value: regula falsi from the grid's linear estimate, bracket kept, Illinois-style (an end kept
// twice has its value halved, so a curved field does not stall one end). Staying on the edge keeps
// every triangle wound as its case in the table says. All edges of a brick step together, one batch per step.
struct EdgeZero {
  IllinoisBracket<glm::vec3> e;
  bool done = false;
  glm::vec3 guess() const { return glm::mix(e.a, e.b, e.fa / (e.fa - e.fb)); }
  void update(const glm::vec3& p, float fp) {
    if (std::abs(fp) < 1e-6f) {
      e.a = e.b = p, done = true;
      return;
    }
    e.narrow(p, fp);
  }
  glm::vec3 result() const { return done ? e.a : guess(); }
};

glm::uvec3 cornerOffset(std::uint32_t n) { return {n & 1u, (n >> 1) & 1u, (n >> 2) & 1u}; }

// A crossed axis edge's vertex belongs to the cell whose lowest node is the edge's lower end (its
// first corner): each cell owns the three edges leaving its corner 0 in +x, +y, +z.
struct Brick {
  glm::uvec3 cellLo{0}, cellHi{0};        // cells [cellLo, cellHi)
  std::vector<std::int32_t> edgeVertex;   // per cell of the brick (local index) * 3 + axis: local vertex or -1
  std::vector<std::uint32_t> edgeOwner;   // per local vertex: local cell * 3 + axis
  std::vector<std::uint32_t> crossed;     // crossed cells: local cell << 8 | case (inside corners)
  std::vector<std::uint32_t> indices;     // triangles, global vertex indices
  std::uint32_t base = 0;                 // global index of local vertex 0
};

class Mesher {
 public:
  Mesher(const SdfGrid& g, const LevelSetBand& band, std::uint32_t stride)
      : g_(g), band_(band), s_(stride), dims_((g.dims - 1u) / stride + 1u), brickCells_(band.brickCells / stride) {
    for (std::uint32_t z = 0; z < band.bricks.z; ++z)
      for (std::uint32_t y = 0; y < band.bricks.y; ++y)
        for (std::uint32_t x = 0; x < band.bricks.x; ++x) {
          const std::int32_t slot = band.nearSlot[band.brickIndex({x, y, z})];
          if (slot < 0) continue;
          if (std::size_t(slot) >= bricks_.size()) bricks_.resize(std::size_t(slot) + 1);
          Brick& b = bricks_[std::size_t(slot)];
          b.cellLo = glm::uvec3(x, y, z) * brickCells_;
          b.cellHi = glm::max(glm::min(b.cellLo + brickCells_, dims_ - 1u), b.cellLo);  // may hold no mesh cell
        }
  }

  HeadMesh run() {
    parallelFor(bricks_.size(), [&](std::size_t s) { findEdges(bricks_[s]); }, 4);
    std::uint32_t vertices = 0;
    for (Brick& b : bricks_) b.base = vertices, vertices += std::uint32_t(b.edgeOwner.size());
    mesh_.positions.resize(vertices);
    mesh_.normals.resize(vertices);
    parallelFor(bricks_.size(), [&](std::size_t s) { placeVertices(std::int32_t(s)); }, 4);
    parallelFor(bricks_.size(), [&](std::size_t s) { triangulate(bricks_[s]); }, 4);
    std::size_t indices = 0;
    for (const Brick& b : bricks_) indices += b.indices.size();
    mesh_.indices.reserve(indices);
    for (Brick& b : bricks_) mesh_.indices.insert(mesh_.indices.end(), b.indices.begin(), b.indices.end());
    return std::move(mesh_);
  }

 private:
  const SdfGrid& g_;
  const LevelSetBand& band_;
  const std::uint32_t s_;           // mesh nodes are every s_-th grid node
  const glm::uvec3 dims_;           // mesh nodes per axis
  const std::uint32_t brickCells_;  // mesh cells per brick side
  const std::array<MarchingCase, 256>& cases_ = marchingCases();
  std::vector<Brick> bricks_;
  HeadMesh mesh_;

  static std::uint32_t local(const glm::uvec3& l, const glm::uvec3& size) { return (l.z * size.y + l.y) * size.x + l.x; }
  glm::uvec3 cellOf(const Brick& b, std::uint32_t l) const {
    const glm::uvec3 s = b.cellHi - b.cellLo;
    return b.cellLo + glm::uvec3(l % s.x, (l / s.x) % s.y, l / (s.x * s.y));
  }
  float value(const glm::uvec3& n) const { return g_.at(n.x * s_, n.y * s_, n.z * s_); }
  glm::vec3 node(const glm::uvec3& n) const { return g_.node(n.x * s_, n.y * s_, n.z * s_); }

  // A crossed cell must not touch the grid's boundary (its upper neighbours own some of its edges).
  void checkInside(const glm::uvec3& c) const {
    if (c.x == 0 || c.y == 0 || c.z == 0 || c.x + 2 == dims_.x || c.y + 2 == dims_.y || c.z + 2 == dims_.z)
      throw Error("level set mesh: the surface reaches the edge of the grid (it is not closed inside it)");
  }

  // Whether the brick's nodes ([cellLo, cellHi], owned by it and its upper neighbours) may have both
  // signs, from the band's summaries (without them: yes).
  bool mayCross(const Brick& b) const {
    if (band_.signs.empty()) return true;
    const glm::uvec3 brick = b.cellLo / brickCells_;
    std::uint8_t signs = 0;
    for (std::uint32_t d = 0; d < 8; ++d) {
      const glm::uvec3 n = brick + cornerOffset(d);
      if (glm::all(glm::lessThan(n, band_.bricks))) signs |= band_.signs[band_.brickIndex(n)];
    }
    return signs == (LevelSetBand::kSomeInside | LevelSetBand::kSomeOutside);
  }

  // The brick's nodes' signs (read once each) as one bit mask per row of nodes along x, then per cell
  // its case and its crossed edges; rows of cells whose four node rows agree are skipped.
  void findEdges(Brick& b) {
    const glm::uvec3 s = b.cellHi - b.cellLo, n = s + 1u;  // n.x <= 33: a row fits in 64 bits
    if (s.x == 0 || s.y == 0 || s.z == 0 || !mayCross(b)) return;
    thread_local std::vector<std::uint64_t> rows;  // bit x of rows[y + n.y z]: node cellLo + (x, y, z) is inside
    rows.resize(std::size_t(n.y) * n.z);
    const std::size_t rowStep = std::size_t(s_) * g_.dims.x, sliceStep = rowStep * g_.dims.y;
    const float* first = &g_.values[g_.index(b.cellLo.x * s_, b.cellLo.y * s_, b.cellLo.z * s_)];
    const std::uint64_t full = (std::uint64_t(1) << n.x) - 1u;
    std::uint64_t some = 0, every = full;
    for (std::uint32_t z = 0; z < n.z; ++z)
      for (std::uint32_t y = 0; y < n.y; ++y) {
        const float* row = first + z * sliceStep + y * rowStep;
        std::uint64_t mask = 0;
        for (std::uint32_t x = 0; x < n.x; ++x) mask |= std::uint64_t(row[std::size_t(x) * s_] < 0.0f) << x;
        rows[y + n.y * z] = mask, some |= mask, every &= mask;
      }
    if (some == 0 || every == full) return;  // in the band, not crossed
    b.edgeVertex.assign(std::size_t(s.x) * s.y * s.z * 3, -1);
    std::size_t triangles = 0;
    for (std::uint32_t z = 0; z < s.z; ++z)
      for (std::uint32_t y = 0; y < s.y; ++y) {
        const std::uint64_t r00 = rows[y + n.y * z], r10 = rows[y + 1 + n.y * z], r01 = rows[y + n.y * (z + 1)],
                            r11 = rows[y + 1 + n.y * (z + 1)];
        if ((r00 | r10 | r01 | r11) == 0 || (r00 & r10 & r01 & r11) == full) continue;
        for (std::uint32_t x = 0; x < s.x; ++x) {
          const std::uint32_t inside = std::uint32_t((r00 >> x) & 3u) | std::uint32_t((r10 >> x) & 3u) << 2 |
                                       std::uint32_t((r01 >> x) & 3u) << 4 | std::uint32_t((r11 >> x) & 3u) << 6;
          if (inside == 0 || inside == 255) continue;
          checkInside(b.cellLo + glm::uvec3(x, y, z));
          const std::uint32_t cell = local({x, y, z}, s);
          b.crossed.push_back(cell << 8 | inside);
          triangles += cases_[inside].triangleCount;
          for (std::uint32_t axis = 0; axis < 3; ++axis)
            if (((inside >> (1u << axis)) & 1u) != (inside & 1u)) {
              b.edgeVertex[cell * 3 + axis] = std::int32_t(b.edgeOwner.size());
              b.edgeOwner.push_back(cell * 3 + axis);
            }
        }
      }
    b.indices.reserve(3 * triangles);
  }

  // Buffers a thread reuses from brick to brick (no allocation per brick once they have grown).
  struct Scratch {
    std::vector<EdgeZero> edges;
    std::vector<glm::vec3> points;
    std::vector<float> at;
    std::vector<std::uint32_t> active;
  };

  void placeVertices(std::int32_t slot) {
    const Brick& b = bricks_[std::size_t(slot)];
    if (b.edgeOwner.empty()) return;
    thread_local Scratch scratch;
    auto& [edges, points, at, active] = scratch;
    edges.clear();
    for (std::uint32_t owner : b.edgeOwner) {
      const glm::uvec3 c = cellOf(b, owner / 3), e = c + cornerOffset(1u << (owner % 3));
      edges.push_back({{node(c), node(e), value(c), value(e)}});
    }
    for (int step = 0; step < 10; ++step) {
      points.clear(), active.clear();
      for (std::uint32_t v = 0; v < edges.size(); ++v)
        if (!edges[v].done) active.push_back(v), points.push_back(edges[v].guess());
      if (active.empty()) break;
      at.resize(points.size());
      band_.exactMany(slot, points, at);
      for (std::size_t i = 0; i < active.size(); ++i) edges[active[i]].update(points[i], at[i]);
    }
    // Normals: the field's gradient from four probes at the corners of a tetrahedron around the
    // vertex (sum of k f(p + h k) / 4h, second order like central differences, two probes fewer),
    // all vertices' probes in one batch.
    constexpr std::array<glm::vec3, 4> kProbe{{{1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}, {1, 1, 1}}};
    const float h = 0.05f * g_.cell;  // sqrt(3) h: within the 0.1 grid cell the band's programs hold past a brick
    points.clear();
    for (std::size_t v = 0; v < edges.size(); ++v) {
      const glm::vec3 p = edges[v].result();
      mesh_.positions[b.base + v] = p;
      for (const glm::vec3& k : kProbe) points.push_back(p + h * k);
    }
    at.resize(points.size());
    band_.exactMany(slot, points, at);
    for (std::size_t v = 0; v < edges.size(); ++v) {
      const float* q = &at[4 * v];
      mesh_.normals[b.base + v] = glm::normalize(q[0] * kProbe[0] + q[1] * kProbe[1] + q[2] * kProbe[2] + q[3] * kProbe[3]);
    }
  }

  // The vertex on the edge from mesh node t along axis: owned by the cell whose lowest node is t,
  // in this brick or (on its upper faces) in a neighbouring one.
  std::uint32_t edgeVertex(const Brick& b, const glm::uvec3& t, std::uint32_t axis) const {
    const Brick* owner = &b;
    if (glm::any(glm::greaterThanEqual(t, b.cellHi))) {
      const std::int32_t slot = band_.nearSlot[band_.brickIndex(t / brickCells_)];
      owner = slot < 0 ? nullptr : &bricks_[std::size_t(slot)];
    }
    const std::int32_t v = owner && !owner->edgeVertex.empty()
                               ? owner->edgeVertex[local(t - owner->cellLo, owner->cellHi - owner->cellLo) * 3 + axis]
                               : -1;
    if (v < 0) throw Error("level set mesh: a crossed edge has no vertex (the band misses a crossed cell)");
    return owner->base + std::uint32_t(v);
  }

  // Each crossed cell's case from the table; its edges' vertices looked up once per cell.
  void triangulate(Brick& b) {
    for (std::uint32_t entry : b.crossed) {
      const glm::uvec3 c = cellOf(b, entry >> 8);
      const MarchingCase& mc = cases_[entry & 255u];
      std::array<std::int64_t, 12> vertex;
      vertex.fill(-1);
      for (std::uint32_t i = 0; i < 3u * mc.triangleCount; ++i) {
        const std::uint32_t e = mc.edges[i];
        if (vertex[e] < 0) vertex[e] = edgeVertex(b, c + cornerOffset(edgeCorner(e)), edgeAxis(e));
        b.indices.push_back(std::uint32_t(vertex[e]));
      }
    }
  }
};
}  // namespace

LevelSetBand wholeGridBand(const SdfGrid& grid, const DistanceFunction& field) {
  LevelSetBand band;
  band.bricks = (grid.dims - 1u + band.brickCells - 1u) / band.brickCells;
  band.nearSlot.resize(std::size_t(band.bricks.x) * band.bricks.y * band.bricks.z);
  for (std::size_t i = 0; i < band.nearSlot.size(); ++i) band.nearSlot[i] = std::int32_t(i);
  band.exact = [field](std::int32_t, const glm::vec3& p) { return field(p); };
  band.exactMany = [field](std::int32_t, std::span<const glm::vec3> points, std::span<float> out) {
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = field(points[i]);
  };
  return band;
}

HeadMesh meshZeroLevel(const SdfGrid& grid, const LevelSetBand& band, std::uint32_t stride) {
  if (grid.empty() || glm::any(glm::lessThan(grid.dims, glm::uvec3(2)))) throw Error("level set mesh: the grid is empty");
  if (band.brickCells == 0 || band.brickCells > 32)
    throw Error("level set mesh: bricks of 1 to 32 cells (a row of a brick's nodes is one 64-bit mask)");
  if (stride == 0 || band.brickCells % stride != 0)
    throw Error("level set mesh: the stride must divide the band's brick size");
  if (glm::any(glm::lessThan((grid.dims - 1u) / stride, glm::uvec3(1))))
    throw Error("level set mesh: the grid has fewer than two nodes per axis at this stride");
  if (band.brickCells == 0 || band.nearSlot.size() != std::size_t(band.bricks.x) * band.bricks.y * band.bricks.z ||
      glm::any(glm::lessThan(band.bricks * band.brickCells, grid.dims - 1u)))
    throw Error("level set mesh: the band's bricks do not cover the grid");
  if (!band.signs.empty() && band.signs.size() != band.nearSlot.size())
    throw Error("level set mesh: the band's sign summaries are not one per brick");
  if (!band.exact || !band.exactMany) throw Error("level set mesh: the band has no exact field");
  return Mesher(grid, band, stride).run();
}

HeadMesh meshZeroLevel(const SdfGrid& grid, const DistanceFunction& field) {
  if (grid.empty() || glm::any(glm::lessThan(grid.dims, glm::uvec3(2)))) throw Error("level set mesh: the grid is empty");
  return meshZeroLevel(grid, wholeGridBand(grid, field));
}
}  // namespace hp
