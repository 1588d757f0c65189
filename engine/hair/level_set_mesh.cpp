#include "engine/hair/level_set_mesh.h"

#include <array>
#include <cstdint>
#include <vector>

#include "engine/error.h"
#include "engine/hair/parallel_for.h"

namespace hp {
namespace {
// The zero of the field on an edge a-b whose grid values fa, fb differ in sign, to 1 micrometre of
// field value: regula falsi from the grid's linear estimate, bracket kept, Illinois-style (an end kept
// twice has its value halved, so a curved field does not stall one end). Staying on the edge keeps
// every triangle wound like its tetrahedron. All edges of a brick step together, one batch per step.
struct EdgeZero {
  glm::vec3 a, b;
  float fa, fb;
  int kept = 0;  // +n: a kept n times in a row, -n: b
  bool done = false;
  glm::vec3 guess() const { return glm::mix(a, b, fa / (fa - fb)); }
  void update(const glm::vec3& p, float fp) {
    if (std::abs(fp) < 1e-6f) {
      a = b = p, done = true;
      return;
    }
    if ((fp < 0.0f) == (fa < 0.0f)) {
      a = p, fa = fp, kept = kept < 0 ? kept - 1 : -1;
      if (kept <= -2) fb *= 0.5f;
    } else {
      b = p, fb = fp, kept = kept > 0 ? kept + 1 : 1;
      if (kept >= 2) fa *= 0.5f;
    }
  }
  glm::vec3 result() const { return done ? a : guess(); }
};

// The six tetrahedra of a cube (corner n = x + 2y + 4z): paths 0 -> 0+e_a -> 0+e_a+e_b -> 7. Every
// edge joins a corner u to a corner v ⊃ u (as bit sets), i.e. node c+u to node c+u+d with d = v ^ u:
// one of the 7 edges leaving node c+u in a positive direction, which lie in the cell whose lowest node
// is c+u. That cell owns the edge's vertex.
constexpr std::array<std::array<std::uint32_t, 4>, 6> kTets{{
    {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

glm::uvec3 cornerOffset(std::uint32_t n) { return {n & 1u, (n >> 1) & 1u, (n >> 2) & 1u}; }

struct Brick {
  glm::uvec3 cellLo{0}, cellHi{0};        // cells [cellLo, cellHi)
  std::vector<std::int32_t> edgeVertex;   // per cell of the brick and direction 1..7: local vertex or -1
  std::vector<std::uint32_t> edgeCell;    // per local vertex: cell (local index) * 8 + direction
  std::vector<glm::uvec3> crossedCells;   // found by findEdges, triangulated later
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
    for (Brick& b : bricks_) b.base = vertices, vertices += std::uint32_t(b.edgeCell.size());
    mesh_.positions.resize(vertices);
    mesh_.normals.resize(vertices);
    parallelFor(bricks_.size(), [&](std::size_t s) { placeVertices(std::int32_t(s)); }, 4);
    parallelFor(bricks_.size(), [&](std::size_t s) { triangulate(bricks_[s]); }, 4);
    for (Brick& b : bricks_) mesh_.indices.insert(mesh_.indices.end(), b.indices.begin(), b.indices.end());
    return std::move(mesh_);
  }

 private:
  const SdfGrid& g_;
  const LevelSetBand& band_;
  const std::uint32_t s_;           // mesh nodes are every s_-th grid node
  const glm::uvec3 dims_;           // mesh nodes per axis
  const std::uint32_t brickCells_;  // mesh cells per brick side
  std::vector<Brick> bricks_;
  HeadMesh mesh_;

  glm::uvec3 brickSize(const Brick& b) const { return b.cellHi - b.cellLo; }
  std::uint32_t localCell(const Brick& b, const glm::uvec3& c) const {
    const glm::uvec3 s = brickSize(b), l = c - b.cellLo;
    return (l.z * s.y + l.y) * s.x + l.x;
  }
  float value(const glm::uvec3& n) const { return g_.at(n.x * s_, n.y * s_, n.z * s_); }
  glm::vec3 node(const glm::uvec3& n) const { return g_.node(n.x * s_, n.y * s_, n.z * s_); }

  // A cell the surface crosses: some corner inside, some not. Such a cell must not touch the boundary.
  bool crossed(const glm::uvec3& c) const {
    bool anyIn = false, anyOut = false;
    for (std::uint32_t n = 0; n < 8; ++n) (value(c + cornerOffset(n)) < 0.0f ? anyIn : anyOut) = true;
    if (!anyIn || !anyOut) return false;
    if (c.x == 0 || c.y == 0 || c.z == 0 || c.x + 2 == dims_.x || c.y + 2 == dims_.y || c.z + 2 == dims_.z)
      throw Error("level set mesh: the surface reaches the edge of the grid (it is not closed inside it)");
    return true;
  }

  template <typename Visit>
  void forCrossedCells(const Brick& b, Visit&& visit) const {
    for (std::uint32_t z = b.cellLo.z; z < b.cellHi.z; ++z)
      for (std::uint32_t y = b.cellLo.y; y < b.cellHi.y; ++y)
        for (std::uint32_t x = b.cellLo.x; x < b.cellHi.x; ++x)
          if (crossed({x, y, z})) visit(glm::uvec3(x, y, z));
  }

  void findEdges(Brick& b) {
    const glm::uvec3 s = brickSize(b);
    b.edgeVertex.assign(std::size_t(s.x) * s.y * s.z * 7, -1);
    forCrossedCells(b, [&](const glm::uvec3& c) {
      b.crossedCells.push_back(c);
      const bool inside = value(c) < 0.0f;
      for (std::uint32_t d = 1; d < 8; ++d)
        if ((value(c + cornerOffset(d)) < 0.0f) != inside) {
          b.edgeVertex[std::size_t(localCell(b, c)) * 7 + d - 1] = std::int32_t(b.edgeCell.size());
          b.edgeCell.push_back(localCell(b, c) * 8 + d);
        }
    });
  }

  void placeVertices(std::int32_t slot) {
    const Brick& b = bricks_[std::size_t(slot)];
    const glm::uvec3 s = brickSize(b);
    std::vector<EdgeZero> edges;
    edges.reserve(b.edgeCell.size());
    for (std::uint32_t edge : b.edgeCell) {
      const std::uint32_t cell = edge / 8;
      const glm::uvec3 c = b.cellLo + glm::uvec3(cell % s.x, (cell / s.x) % s.y, cell / (s.x * s.y));
      const glm::uvec3 e = c + cornerOffset(edge % 8);
      edges.push_back({node(c), node(e), value(c), value(e)});
    }
    std::vector<glm::vec3> points;
    std::vector<float> at;
    std::vector<std::size_t> active;
    for (int step = 0; step < 10; ++step) {
      points.clear(), active.clear();
      for (std::size_t v = 0; v < edges.size(); ++v)
        if (!edges[v].done) active.push_back(v), points.push_back(edges[v].guess());
      if (active.empty()) break;
      at.resize(points.size());
      band_.exactMany(slot, points, at);
      for (std::size_t i = 0; i < active.size(); ++i) edges[active[i]].update(points[i], at[i]);
    }
    // Normals: central differences of the field, the six probes of every vertex in one batch.
    const float h = 0.05f * g_.cell;  // the grid's cell: the band's programs hold 0.1 of it past a brick
    points.clear();
    for (std::size_t v = 0; v < edges.size(); ++v) {
      const glm::vec3 p = edges[v].result();
      mesh_.positions[b.base + v] = p;
      for (int axis = 0; axis < 3; ++axis) {
        glm::vec3 offset(0.0f);
        offset[axis] = h;
        points.push_back(p + offset);
        points.push_back(p - offset);
      }
    }
    at.resize(points.size());
    band_.exactMany(slot, points, at);
    for (std::size_t v = 0; v < edges.size(); ++v) {
      const float* q = &at[6 * v];
      mesh_.normals[b.base + v] = glm::normalize(glm::vec3(q[0] - q[1], q[2] - q[3], q[4] - q[5]) / (2.0f * h));
    }
  }

  // The vertex on the edge from node t to node t + offset(d), owned by the cell whose lowest node is t.
  std::uint32_t edgeVertex(const glm::uvec3& t, std::uint32_t d) const {
    const glm::uvec3 brick = t / brickCells_;
    const std::int32_t slot = band_.nearSlot[band_.brickIndex(brick)];
    const std::int32_t local =
        slot < 0 ? -1 : bricks_[std::size_t(slot)].edgeVertex[std::size_t(localCell(bricks_[std::size_t(slot)], t)) * 7 + d - 1];
    if (local < 0) throw Error("level set mesh: a crossed edge has no vertex (the band misses a crossed cell)");
    return bricks_[std::size_t(slot)].base + std::uint32_t(local);
  }

  // Per crossed cell: which corners are inside (bit n: corner n), and the vertices of its edges looked
  // up once (key lower corner * 8 + upper corner), shared by its six tetrahedra.
  struct CellCuts {
    std::uint32_t inside = 0;
    std::array<std::int64_t, 64> vertex;
  };

  void triangulate(Brick& b) {
    for (const glm::uvec3& c : b.crossedCells) {
      CellCuts cell;
      for (std::uint32_t n = 0; n < 8; ++n) cell.inside |= std::uint32_t(value(c + cornerOffset(n)) < 0.0f) << n;
      cell.vertex.fill(-1);
      for (const auto& t : kTets) tetrahedron(b, c, cell, t);
    }
  }

  // Orientation is decided on the tetrahedron's corners, never on the (possibly tiny) triangle: a
  // vertex cut on edge a-b moves from a toward b, so the cut triangle is wound like its corners.
  static void emit(Brick& b, std::uint32_t v0, std::uint32_t v1, std::uint32_t v2, bool flip) {
    if (flip) std::swap(v1, v2);
    b.indices.insert(b.indices.end(), {v0, v1, v2});
  }

  // Orientation from the corners' offsets in the cell (exact small integers: the same decisions as
  // world positions, which are the offsets scaled by the cell and moved).
  void tetrahedron(Brick& b, const glm::uvec3& c, CellCuts& cell, const std::array<std::uint32_t, 4>& corner) const {
    std::array<glm::vec3, 4> pos;
    std::array<int, 4> in{}, out{};
    int nIn = 0, nOut = 0;
    for (int v = 0; v < 4; ++v) {
      pos[v] = glm::vec3(cornerOffset(corner[v]));
      ((cell.inside >> corner[v]) & 1u ? in[nIn++] : out[nOut++]) = v;
    }
    if (nIn == 0 || nOut == 0) return;
    auto cut = [&](int u, int v) {
      std::uint32_t lo = corner[u], hi = corner[v];
      if ((lo & hi) != lo) std::swap(lo, hi);  // the subset corner is the edge's lower node
      std::int64_t& known = cell.vertex[lo * 8 + hi];
      if (known < 0) known = edgeVertex(c + cornerOffset(lo), lo ^ hi);
      return std::uint32_t(known);
    };
    if (nIn == 1 || nOut == 1) {
      const int apex = nIn == 1 ? in[0] : out[0];
      const std::array<int, 3> r = nIn == 1 ? std::array<int, 3>{out[0], out[1], out[2]}
                                            : std::array<int, 3>{in[0], in[1], in[2]};
      const glm::vec3 n = glm::cross(pos[r[1]] - pos[r[0]], pos[r[2]] - pos[r[0]]);
      const bool facesAwayFromApex = glm::dot(n, pos[r[0]] - pos[apex]) > 0.0f;
      // Outside is away from a lone inside corner, toward a lone outside one.
      emit(b, cut(apex, r[0]), cut(apex, r[1]), cut(apex, r[2]), facesAwayFromApex != (nIn == 1));
      return;
    }
    // Two in, two out: the quad through the four crossed edges, in cyclic order. Its normal is that
    // of the midpoint parallelogram, (o1 - o0) x (i1 - i0); outside is toward the out corners.
    const glm::vec3 &i0 = pos[in[0]], &i1 = pos[in[1]], &o0 = pos[out[0]], &o1 = pos[out[1]];
    const bool flip = glm::dot(glm::cross(o1 - o0, i1 - i0), (o0 + o1) - (i0 + i1)) < 0.0f;
    const std::uint32_t q0 = cut(in[0], out[0]), q1 = cut(in[0], out[1]), q2 = cut(in[1], out[1]),
                        q3 = cut(in[1], out[0]);
    emit(b, q0, q1, q2, flip);
    emit(b, q0, q2, q3, flip);
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
  if (stride == 0 || band.brickCells % stride != 0)
    throw Error("level set mesh: the stride must divide the band's brick size");
  if (glm::any(glm::lessThan((grid.dims - 1u) / stride, glm::uvec3(1))))
    throw Error("level set mesh: the grid has fewer than two nodes per axis at this stride");
  if (band.brickCells == 0 || band.nearSlot.size() != std::size_t(band.bricks.x) * band.bricks.y * band.bricks.z ||
      glm::any(glm::lessThan(band.bricks * band.brickCells, grid.dims - 1u)))
    throw Error("level set mesh: the band's bricks do not cover the grid");
  if (!band.exact || !band.exactMany) throw Error("level set mesh: the band has no exact field");
  return Mesher(grid, band, stride).run();
}

HeadMesh meshZeroLevel(const SdfGrid& grid, const DistanceFunction& field) {
  if (grid.empty() || glm::any(glm::lessThan(grid.dims, glm::uvec3(2)))) throw Error("level set mesh: the grid is empty");
  return meshZeroLevel(grid, wholeGridBand(grid, field));
}
}  // namespace hp
