#include "engine/core/hair/mesh_simplify.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <string>
#include <unordered_map>

#include "engine/core/error.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/number_text.h"

namespace hp {
namespace {
void validate(const HeadMesh& mesh, const SimplifyOptions& options) {
  if (!(options.maxError >= 0.0f) || !std::isfinite(options.maxError))
    throw Error("simplify mesh: maxError must be finite and >= 0, got " + numberText(options.maxError));
  if (!(options.maxNormalDegrees >= 0.0f && options.maxNormalDegrees <= 180.0f))
    throw Error("simplify mesh: maxNormalDegrees must be in [0, 180], got " + numberText(options.maxNormalDegrees));
  requireMeshShape(mesh, "simplify mesh");
  const auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!finite(mesh.positions[i])) throw Error("simplify mesh: vertex " + numberText(double(i)) + " is not finite");
    const float length = glm::length(mesh.normals[i]);
    if (!finite(mesh.normals[i]) || !(std::abs(length - 1.0f) < 1e-3f))
      throw Error("simplify mesh: normal " + numberText(double(i)) + " is not a unit vector (length " +
                  numberText(length) + ")");
  }
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
  double cost;
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
    return glm::dot(a, b) >= minCos_ && glm::dot(a, c) >= minCos_ && glm::dot(b, c) >= minCos_;
  }

  // Vertices of uneven triangles, of edges not wound once each way by two triangles (open, non-manifold or
  // inconsistently wound) and pinched ones (whose triangles do not close one ring around them) never move.
  void lockUnevenAndBorders() {
    std::unordered_map<std::uint64_t, std::uint32_t> directed;
    const auto key = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t(a) << 32) | b; };
    for (const glm::uvec3& t : triangles_) {
      if (!even(t)) locked_[t.x] = locked_[t.y] = locked_[t.z] = 1;
      for (int k = 0; k < 3; ++k) ++directed[key(t[k], t[(k + 1) % 3])];
    }
    for (const auto& [edge, count] : directed) {
      const std::uint32_t a = std::uint32_t(edge >> 32), b = std::uint32_t(edge);
      const auto back = directed.find(key(b, a));
      if (count != 1 || back == directed.end() || back->second != 1) locked_[a] = locked_[b] = 1;
    }
    for (std::uint32_t v = 0; v < fans_.size(); ++v)
      if (!oneRing(v)) locked_[v] = 1;
  }

  // Whether v's triangles, each seen as the edge opposite v in its winding, chain into one closed loop.
  bool oneRing(std::uint32_t v) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> link;  // (next, after) around v
    for (const std::uint32_t t : fans_[v]) {
      const glm::uvec3& tri = triangles_[t];
      const int k = tri.x == v ? 0 : tri.y == v ? 1 : 2;
      link.emplace_back(tri[(k + 1) % 3], tri[(k + 2) % 3]);
    }
    if (link.empty()) return true;  // unused: nothing to move
    std::uint32_t at = link.front().first;
    for (std::size_t steps = 0; steps < link.size(); ++steps) {
      const auto next = std::find_if(link.begin(), link.end(), [&](const auto& e) { return e.first == at; });
      if (next == link.end()) return false;
      at = next->second;
      if (at == link.front().first) return steps + 1 == link.size();
    }
    return false;
  }

  bool contains(const glm::uvec3& t, std::uint32_t v) const { return t.x == v || t.y == v || t.z == v; }
  // Triangle t with vertex `from` moved onto `to`.
  static glm::uvec3 moved(glm::uvec3 t, std::uint32_t from, std::uint32_t to) {
    for (int k = 0; k < 3; ++k)
      if (t[k] == from) t[k] = to;
    return t;
  }

  void push(std::uint32_t from, std::uint32_t to) {
    if (locked_[from]) return;
    const double cost = (quadrics_[from] + quadrics_[to]).at(glm::dvec3(mesh_.positions[to]));
    if (cost <= maxCost_) queue_.push({cost, from, to, versions_[from] + versions_[to]});
  }

  glm::dvec3 normalOf(const glm::uvec3& t) const {
    const glm::dvec3 a(mesh_.positions[t.x]);
    return glm::cross(glm::dvec3(mesh_.positions[t.y]) - a, glm::dvec3(mesh_.positions[t.z]) - a);
  }

  // The edge from-to is interior (two living triangles), the rings of its ends meet only at those triangles'
  // third vertices and no moved triangle repeats a living one (the mesh stays manifold: a tetrahedron does not
  // fold into a two-sided sheet), and every triangle that moves stays even, keeps some area and faces as its
  // vertex normals do (within 45 degrees of each, or no further off than it was).
  bool collapsible(std::uint32_t from, std::uint32_t to) const {
    std::uint32_t shared = 0;
    for (const std::uint32_t t : fans_[from]) {
      if (!alive_[t]) continue;
      if (contains(triangles_[t], to)) {
        ++shared;
        continue;
      }
      const glm::uvec3 after = moved(triangles_[t], from, to);
      if (!even(after) || !facesAsBefore(triangles_[t], after)) return false;
    }
    return shared == 2 && commonNeighbours(from, to) == 2 && !repeatsALivingTriangle(from, to);
  }

  bool facesAsBefore(const glm::uvec3& before, const glm::uvec3& after) const {
    const glm::dvec3 was = normalOf(before), is = normalOf(after);
    if (!(glm::length(is) > 1e-3 * glm::length(was)) || glm::dot(was, is) < 0.5 * glm::length(was) * glm::length(is))
      return false;
    const double limit = std::cos(glm::radians(45.0));
    const glm::dvec3 unitIs = glm::normalize(is);
    for (int k = 0; k < 3; ++k) {
      const double wasFacing = glm::length(was) > 0.0 ? glm::dot(glm::normalize(was), glm::dvec3(mesh_.normals[before[k]])) : limit;
      if (glm::dot(unitIs, glm::dvec3(mesh_.normals[after[k]])) < std::min(limit, wasFacing)) return false;
    }
    return true;
  }

  // Whether moving `from` onto `to` makes a triangle with the same three vertices as one already at `to`.
  bool repeatsALivingTriangle(std::uint32_t from, std::uint32_t to) const {
    const auto sorted = [](glm::uvec3 t) {
      std::sort(&t.x, &t.x + 3);
      return t;
    };
    for (const std::uint32_t t : fans_[from]) {
      if (!alive_[t] || contains(triangles_[t], to)) continue;
      const glm::uvec3 after = sorted(moved(triangles_[t], from, to));
      for (const std::uint32_t u : fans_[to])
        if (alive_[u] && !contains(triangles_[u], from) && sorted(triangles_[u]) == after) return true;
    }
    return false;
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
      triangles_[t] = moved(triangles_[t], from, to);
      fans_[to].push_back(t);
    }
    fans_[from].clear();
    std::erase_if(fans_[to], [&](std::uint32_t t) { return !alive_[t]; });
    quadrics_[to] = quadrics_[to] + quadrics_[from];
    ++versions_[from];  // its entries are dead
    ++versions_[to];    // every edge at `to` now costs more; the others are unchanged
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
  mutable std::vector<std::uint64_t> marks_;  // commonNeighbours' and collapse's scratch: a vertex seen this stamp
  mutable std::uint64_t stamp_ = 0;
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
  if (mesh.indices.empty()) return {};  // no triangle uses a vertex
  return compact(mesh, Collapser(mesh, options).run());
}
}  // namespace hp
