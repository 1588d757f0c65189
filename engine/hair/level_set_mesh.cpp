#include "engine/hair/level_set_mesh.h"

#include <array>
#include <cstdint>
#include <unordered_map>

#include "engine/error.h"

namespace hp {
namespace {
glm::vec3 fieldGradient(const DistanceFunction& f, const glm::vec3& p, float h) {
  return glm::vec3(f(p + glm::vec3(h, 0, 0)) - f(p - glm::vec3(h, 0, 0)),
                   f(p + glm::vec3(0, h, 0)) - f(p - glm::vec3(0, h, 0)),
                   f(p + glm::vec3(0, 0, h)) - f(p - glm::vec3(0, 0, h))) /
         (2.0f * h);
}

// The zero of f on the segment a-b (f(a) < 0 <= f(b) on the grid): regula falsi from the grid's
// linear estimate, bracket kept. Staying on the edge keeps every triangle wound like its tetrahedron.
glm::vec3 zeroOnEdge(const DistanceFunction& f, glm::vec3 a, glm::vec3 b, float fa, float fb) {
  for (int step = 0; step < 12; ++step) {
    const glm::vec3 p = glm::mix(a, b, fa / (fa - fb));
    const float fp = f(p);
    if (std::abs(fp) < 1e-7f) return p;
    if ((fp < 0.0f) == (fa < 0.0f)) a = p, fa = fp;
    else b = p, fb = fp;
  }
  return glm::mix(a, b, fa / (fa - fb));
}

// The six tetrahedra of a cube (corner n = x + 2y + 4z): paths 0 -> 0+e_a -> 0+e_a+e_b -> 7.
constexpr std::array<std::array<std::uint32_t, 4>, 6> kTets{{
    {0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}}};

struct Builder {
  const SdfGrid& g;
  const DistanceFunction& f;
  std::unordered_map<std::uint64_t, std::uint32_t> vertexOfEdge;
  HeadMesh mesh;

  std::uint32_t edgeVertex(std::size_t a, std::size_t b, const glm::vec3& pa, const glm::vec3& pb) {
    if (a > b) return edgeVertex(b, a, pb, pa);
    const std::uint64_t key = std::uint64_t(a) << 32 | std::uint64_t(b);
    auto [it, fresh] = vertexOfEdge.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
    if (fresh) {
      const glm::vec3 p = zeroOnEdge(f, pa, pb, g.values[a], g.values[b]);
      mesh.positions.push_back(p);
      mesh.normals.push_back(glm::normalize(fieldGradient(f, p, 0.05f * g.cell)));
    }
    return it->second;
  }

  // Orientation is decided on the tetrahedron's corners, never on the (possibly tiny) triangle: a
  // vertex cut on edge a-b moves from a toward b, so the cut triangle is wound like its corners.
  void emit(std::uint32_t a, std::uint32_t b, std::uint32_t c, bool flip) {
    if (flip) std::swap(b, c);
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }

  void tetrahedron(const std::array<std::size_t, 4>& node, const std::array<glm::vec3, 4>& pos) {
    std::array<int, 4> in{}, out{};
    int nIn = 0, nOut = 0;
    for (int v = 0; v < 4; ++v) (g.values[node[v]] < 0.0f ? in[nIn++] : out[nOut++]) = v;
    if (nIn == 0 || nOut == 0) return;
    auto cut = [&](int a, int b) { return edgeVertex(node[a], node[b], pos[a], pos[b]); };
    if (nIn == 1 || nOut == 1) {
      const int apex = nIn == 1 ? in[0] : out[0];
      const std::array<int, 3> r = nIn == 1 ? std::array<int, 3>{out[0], out[1], out[2]}
                                            : std::array<int, 3>{in[0], in[1], in[2]};
      const glm::vec3 n = glm::cross(pos[r[1]] - pos[r[0]], pos[r[2]] - pos[r[0]]);
      const bool facesAwayFromApex = glm::dot(n, pos[r[0]] - pos[apex]) > 0.0f;
      // Outside is away from a lone inside corner, toward a lone outside one.
      emit(cut(apex, r[0]), cut(apex, r[1]), cut(apex, r[2]), facesAwayFromApex != (nIn == 1));
      return;
    }
    // Two in, two out: the quad through the four crossed edges, in cyclic order. Its normal is that
    // of the midpoint parallelogram, (o1 - o0) x (i1 - i0); outside is toward the out corners.
    const glm::vec3 &i0 = pos[in[0]], &i1 = pos[in[1]], &o0 = pos[out[0]], &o1 = pos[out[1]];
    const bool flip = glm::dot(glm::cross(o1 - o0, i1 - i0), (o0 + o1) - (i0 + i1)) < 0.0f;
    const std::uint32_t q0 = cut(in[0], out[0]), q1 = cut(in[0], out[1]), q2 = cut(in[1], out[1]),
                        q3 = cut(in[1], out[0]);
    emit(q0, q1, q2, flip);
    emit(q0, q2, q3, flip);
  }

  void cell(std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    std::array<std::size_t, 8> node;
    std::array<glm::vec3, 8> pos;
    bool anyIn = false, anyOut = false;
    for (std::uint32_t n = 0; n < 8; ++n) {
      const std::uint32_t x = i + (n & 1u), y = j + ((n >> 1) & 1u), z = k + ((n >> 2) & 1u);
      node[n] = g.index(x, y, z);
      pos[n] = g.node(x, y, z);
      (g.values[node[n]] < 0.0f ? anyIn : anyOut) = true;
    }
    if (!anyIn || !anyOut) return;
    if (i == 0 || j == 0 || k == 0 || i + 2 == g.dims.x || j + 2 == g.dims.y || k + 2 == g.dims.z)
      throw Error("level set mesh: the surface reaches the edge of the grid (it is not closed inside it)");
    for (const auto& t : kTets)
      tetrahedron({node[t[0]], node[t[1]], node[t[2]], node[t[3]]}, {pos[t[0]], pos[t[1]], pos[t[2]], pos[t[3]]});
  }
};
}  // namespace

HeadMesh meshZeroLevel(const SdfGrid& grid, const DistanceFunction& field) {
  if (grid.empty() || glm::any(glm::lessThan(grid.dims, glm::uvec3(2)))) throw Error("level set mesh: the grid is empty");
  Builder b{grid, field, {}, {}};
  for (std::uint32_t k = 0; k + 1 < grid.dims.z; ++k)
    for (std::uint32_t j = 0; j + 1 < grid.dims.y; ++j)
      for (std::uint32_t i = 0; i + 1 < grid.dims.x; ++i) b.cell(i, j, k);
  return std::move(b.mesh);
}
}  // namespace hp
