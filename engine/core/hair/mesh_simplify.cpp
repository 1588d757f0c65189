#include "engine/core/hair/mesh_simplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <string>
#include <unordered_map>

#include "engine/core/error.h"

namespace hp {
namespace {
void validate(const HeadMesh& mesh, const SimplifyOptions& options) {
  if (!(options.maxError >= 0.0f) || !std::isfinite(options.maxError))
    throw Error("simplify mesh: maxError must be finite and >= 0, got " + std::to_string(options.maxError));
  if (!(options.maxNormalDegrees >= 0.0f && options.maxNormalDegrees <= 180.0f))
    throw Error("simplify mesh: maxNormalDegrees must be in [0, 180], got " + std::to_string(options.maxNormalDegrees));
  if (mesh.indices.size() % 3 != 0)
    throw Error("simplify mesh: " + std::to_string(mesh.indices.size()) + " indices are not whole triangles");
  if (mesh.normals.size() != mesh.positions.size() || (!mesh.scalp.empty() && mesh.scalp.size() != mesh.positions.size()))
    throw Error("simplify mesh: normals and scalp weights must match the " + std::to_string(mesh.positions.size()) +
                " positions");
  for (const std::uint32_t i : mesh.indices)
    if (i >= mesh.positions.size())
      throw Error("simplify mesh: index " + std::to_string(i) + " past the " + std::to_string(mesh.positions.size()) +
                  " vertices");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i].x + mesh.positions[i].y + mesh.positions[i].z))
      throw Error("simplify mesh: vertex " + std::to_string(i) + " is not finite");
}

// The sum over planes n.p + d = 0 of the squared distance (n.p + d)^2, as a symmetric 4x4 matrix.
struct Quadric {
  std::array<double, 10> m{};  // xx xy xz xd yy yz yd zz zd dd

  static Quadric plane(const glm::dvec3& n, double d) {
    return {{n.x * n.x, n.x * n.y, n.x * n.z, n.x * d, n.y * n.y, n.y * n.z, n.y * d, n.z * n.z, n.z * d, d * d}};
  }
  Quadric operator+(const Quadric& o) const {
    Quadric s;
    for (std::size_t i = 0; i < m.size(); ++i) s.m[i] = m[i] + o.m[i];
    return s;
  }
  double at(const glm::dvec3& p) const {
    return m[0] * p.x * p.x + m[4] * p.y * p.y + m[7] * p.z * p.z + m[9] +
           2.0 * (m[1] * p.x * p.y + m[2] * p.x * p.z + m[5] * p.y * p.z + m[3] * p.x + m[6] * p.y + m[8] * p.z);
  }
};

// Moving vertex `from` onto `to`, as it cost when pushed; `versions`: the sum of the two vertices' versions
// then (each only grows, so the sum moves when either does).
struct Candidate {
  float cost;
  std::uint32_t from, to, versions;
  bool operator>(const Candidate& o) const {  // cheapest first; ties by the vertices, so the order is fixed
    return cost != o.cost ? cost > o.cost : from != o.from ? from > o.from : to > o.to;
  }
};

// The collapses of one mesh (the contract's rules). Quadrics only grow as vertices merge, so an edge's cost
// never falls: the first current queue entry above the bound ends the run, and an edge whose end merged is
// pushed again at its new cost (the old entry is stale: a vertex's version moved on).
class Collapser {
 public:
  Collapser(const HeadMesh& mesh, const SimplifyOptions& options)
      : mesh_(mesh), minCos_(std::cos(glm::radians(double(options.maxNormalDegrees))) - 1e-9),
        maxCost_(double(options.maxError) * options.maxError), target_(options.targetTriangles),
        alive_(mesh.indices.size() / 3, 1), fans_(mesh.positions.size()), locked_(mesh.positions.size(), 0),
        quadrics_(mesh.positions.size()), versions_(mesh.positions.size(), 0), marks_(mesh.positions.size(), 0) {
    for (std::size_t t = 0; t < alive_.size(); ++t) {
      triangles_.emplace_back(mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
      for (int k = 0; k < 3; ++k) fans_[triangles_[t][k]].push_back(std::uint32_t(t));
    }
    living_ = triangles_.size();
    lockUnevenAndBorders();
    for (const glm::uvec3& t : triangles_) {
      const glm::dvec3 a(mesh.positions[t.x]), n = glm::cross(glm::dvec3(mesh.positions[t.y]) - a,
                                                              glm::dvec3(mesh.positions[t.z]) - a);
      if (glm::length(n) == 0.0) continue;  // a degenerate triangle has no plane
      const glm::dvec3 unit = glm::normalize(n);
      const Quadric q = Quadric::plane(unit, -glm::dot(unit, a));
      for (int k = 0; k < 3; ++k) quadrics_[t[k]] = quadrics_[t[k]] + q;
    }
    for (const glm::uvec3& t : triangles_)
      for (int k = 0; k < 3; ++k)
        if (t[k] < t[(k + 1) % 3]) {  // each interior edge once (its two triangles wind it both ways)
          push(t[k], t[(k + 1) % 3]);
          push(t[(k + 1) % 3], t[k]);
        }
  }

  std::vector<std::uint32_t> run() {
    while (!queue_.empty() && living_ > target_) {
      const Candidate c = queue_.top();
      queue_.pop();
      // Stale: the collapse that moved a version on pushed this edge again at its new cost.
      if (c.versions != versions_[c.from] + versions_[c.to]) continue;
      if (c.cost > maxCost_) break;
      if (collapsible(c.from, c.to)) collapse(c.from, c.to);
    }
    std::vector<std::uint32_t> indices;
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      if (alive_[t]) indices.insert(indices.end(), {triangles_[t].x, triangles_[t].y, triangles_[t].z});
    return indices;
  }

 private:
  bool even(const glm::uvec3& t) const {
    if (!mesh_.scalp.empty() && (mesh_.scalp[t.x] != mesh_.scalp[t.y] || mesh_.scalp[t.x] != mesh_.scalp[t.z]))
      return false;
    const glm::dvec3 a(mesh_.normals[t.x]), b(mesh_.normals[t.y]), c(mesh_.normals[t.z]);
    return std::min({glm::dot(a, b), glm::dot(a, c), glm::dot(b, c)}) >= minCos_;
  }

  // Vertices of uneven triangles and of edges without exactly two triangles never move.
  void lockUnevenAndBorders() {
    std::unordered_map<std::uint64_t, std::uint32_t> edges;
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b); };
    for (const glm::uvec3& t : triangles_) {
      if (!even(t)) locked_[t.x] = locked_[t.y] = locked_[t.z] = 1;
      for (int k = 0; k < 3; ++k) ++edges[key(t[k], t[(k + 1) % 3])];
    }
    for (const auto& [edge, count] : edges)
      if (count != 2) locked_[edge >> 32] = locked_[edge & 0xFFFFFFFFu] = 1;
  }

  bool contains(const glm::uvec3& t, std::uint32_t v) const { return t.x == v || t.y == v || t.z == v; }

  void push(std::uint32_t from, std::uint32_t to) {
    if (locked_[from]) return;
    const double cost = (quadrics_[from] + quadrics_[to]).at(glm::dvec3(mesh_.positions[to]));
    if (cost <= maxCost_) queue_.push({float(cost), from, to, versions_[from] + versions_[to]});
  }

  glm::dvec3 normalOf(const glm::uvec3& t) const {
    const glm::dvec3 a(mesh_.positions[t.x]);
    return glm::cross(glm::dvec3(mesh_.positions[t.y]) - a, glm::dvec3(mesh_.positions[t.z]) - a);
  }

  // The edge from-to is interior (two living triangles), the rings of its ends meet only at those triangles'
  // third vertices (the mesh stays manifold), and every triangle that moves stays even, keeps its facing and
  // keeps some area.
  bool collapsible(std::uint32_t from, std::uint32_t to) const {
    std::uint32_t shared = 0;
    for (const std::uint32_t t : fans_[from]) {
      if (!alive_[t]) continue;
      if (contains(triangles_[t], to)) {
        ++shared;
        continue;
      }
      glm::uvec3 moved = triangles_[t];
      for (int k = 0; k < 3; ++k)
        if (moved[k] == from) moved[k] = to;
      const glm::dvec3 before = normalOf(triangles_[t]), after = normalOf(moved);
      const double lengths = glm::length(before) * glm::length(after);
      if (!even(moved) || !(glm::length(after) > 1e-3 * glm::length(before)) || glm::dot(before, after) < 0.5 * lengths)
        return false;
    }
    return shared == 2 && commonNeighbours(from, to) == 2;
  }

  // How many vertices are neighbours of both a and b (each counted once).
  std::uint32_t commonNeighbours(std::uint32_t a, std::uint32_t b) const {
    ++stamp_;
    for (const std::uint32_t t : fans_[a])
      if (alive_[t])
        for (int k = 0; k < 3; ++k) marks_[triangles_[t][k]] = stamp_;
    std::uint32_t common = 0;
    for (const std::uint32_t t : fans_[b])
      if (alive_[t])
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t w = triangles_[t][k];
          if (w != a && w != b && marks_[w] == stamp_) {
            ++common;
            marks_[w] = 0;  // once
          }
        }
    return common;
  }

  void collapse(std::uint32_t from, std::uint32_t to) {
    for (const std::uint32_t t : fans_[from]) {
      if (!alive_[t]) continue;
      if (contains(triangles_[t], to)) {
        alive_[t] = 0;
        --living_;
        continue;
      }
      for (int k = 0; k < 3; ++k)
        if (triangles_[t][k] == from) triangles_[t][k] = to;
      fans_[to].push_back(t);
    }
    fans_[from].clear();
    std::erase_if(fans_[to], [&](std::uint32_t t) { return !alive_[t]; });
    quadrics_[to] = quadrics_[to] + quadrics_[from];
    ++versions_[to];  // every edge at `to` now costs more; the others are unchanged
    ++stamp_;
    for (const std::uint32_t t : fans_[to])
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t w = triangles_[t][k];
        if (w == to || marks_[w] == stamp_) continue;
        marks_[w] = stamp_;
        push(w, to);
        push(to, w);
      }
  }

  const HeadMesh& mesh_;
  double minCos_, maxCost_;
  std::size_t target_, living_ = 0;
  std::vector<glm::uvec3> triangles_;
  std::vector<char> alive_;
  std::vector<std::vector<std::uint32_t>> fans_;  // per vertex, the triangles that held it (some no longer living)
  std::vector<char> locked_;
  std::vector<Quadric> quadrics_;
  std::vector<std::uint32_t> versions_;
  mutable std::vector<std::uint32_t> marks_;  // commonNeighbours' and collapse's scratch: a vertex seen this stamp
  mutable std::uint32_t stamp_ = 0;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> queue_;
};

// The kept vertices, in the order the indices first use them; the indices renumbered.
HeadMesh compact(const HeadMesh& mesh, std::vector<std::uint32_t> indices) {
  HeadMesh out;
  std::vector<std::uint32_t> remap(mesh.positions.size(), ~0u);
  for (std::uint32_t& i : indices) {
    if (remap[i] == ~0u) {
      remap[i] = std::uint32_t(out.positions.size());
      out.positions.push_back(mesh.positions[i]);
      out.normals.push_back(mesh.normals[i]);
      if (!mesh.scalp.empty()) out.scalp.push_back(mesh.scalp[i]);
    }
    i = remap[i];
  }
  out.indices = std::move(indices);
  return out;
}
}  // namespace

HeadMesh simplifyMesh(const HeadMesh& mesh, const SimplifyOptions& options) {
  validate(mesh, options);
  if (mesh.indices.empty()) return mesh;
  return compact(mesh, Collapser(mesh, options).run());
}
}  // namespace hp
