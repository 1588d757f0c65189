#include "engine/core/hair/convex_hull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace hp {
namespace {
struct Face {
  std::array<int, 3> v;    // counter-clockwise from outside
  std::array<int, 3> adj;  // adj[k]: face across edge (v[k], v[k+1])
  glm::dvec3 n;            // unit outward normal
  double d = 0.0;          // plane: dot(n, x) = d
  std::vector<int> outside;
  bool alive = true;
  int mark = -1;
};

struct HorizonEdge {
  int a, b, neighbour;
};

class Quickhull {
 public:
  Quickhull(std::span<const glm::dvec3> pts, double eps) : p_(pts), eps_(eps) {}

  std::vector<glm::uvec3> run() {
    if (!initialSimplex()) return {};
    while (!pending_.empty()) {
      int f = pending_.back();
      pending_.pop_back();
      if (faces_[f].alive && !faces_[f].outside.empty()) addFarthest(f);
    }
    std::vector<glm::uvec3> out;
    for (const auto& f : faces_)
      if (f.alive) out.emplace_back(f.v[0], f.v[1], f.v[2]);
    return out;
  }

 private:
  double dist(const Face& f, int i) const { return glm::dot(f.n, p_[i]) - f.d; }

  int makeFace(int a, int b, int c) {
    Face f;
    f.v = {a, b, c};
    f.adj = {-1, -1, -1};
    glm::dvec3 n = glm::cross(p_[b] - p_[a], p_[c] - p_[a]);
    double len = glm::length(n);
    f.n = len > 0.0 ? n / len : glm::dvec3(0.0);
    f.d = glm::dot(f.n, p_[a]);
    faces_.push_back(std::move(f));
    return static_cast<int>(faces_.size()) - 1;
  }

  int farthestFrom(auto&& measure) const {
    int best = 0;
    double bestValue = -1.0;
    for (int i = 0; i < int(p_.size()); ++i)
      if (double v = measure(p_[i]); v > bestValue) bestValue = v, best = i;
    return best;
  }

  bool initialSimplex() {
    int a = 0;
    for (int i = 1; i < int(p_.size()); ++i)
      if (p_[i].x < p_[a].x) a = i;
    int b = farthestFrom([&](const glm::dvec3& q) { return glm::length(q - p_[a]); });
    glm::dvec3 ab = p_[b] - p_[a];
    if (glm::length(ab) <= eps_) return false;
    int c = farthestFrom([&](const glm::dvec3& q) { return glm::length(glm::cross(ab, q - p_[a])); });
    glm::dvec3 n = glm::cross(ab, p_[c] - p_[a]);
    if (glm::length(n) <= eps_ * glm::length(ab)) return false;
    n = glm::normalize(n);
    int d = farthestFrom([&](const glm::dvec3& q) { return std::abs(glm::dot(n, q - p_[a])); });
    if (std::abs(glm::dot(n, p_[d] - p_[a])) <= eps_) return false;
    if (glm::dot(n, p_[d] - p_[a]) > 0.0) std::swap(b, c);  // make (a, b, c) face away from d
    buildTetrahedron(a, b, c, d);
    return true;
  }

  void buildTetrahedron(int a, int b, int c, int d) {
    int f0 = makeFace(a, b, c), f1 = makeFace(a, d, b), f2 = makeFace(b, d, c), f3 = makeFace(c, d, a);
    faces_[f0].adj = {f1, f2, f3};
    faces_[f1].adj = {f3, f2, f0};
    faces_[f2].adj = {f1, f3, f0};
    faces_[f3].adj = {f2, f1, f0};
    for (int i = 0; i < int(p_.size()); ++i) {
      if (i == a || i == b || i == c || i == d) continue;
      for (int f : {f0, f1, f2, f3})
        if (dist(faces_[f], i) > eps_) {
          faces_[f].outside.push_back(i);
          break;
        }
    }
    pending_ = {f0, f1, f2, f3};
  }

  // Visible faces from eye (connected set grown from `start`) and the horizon around them.
  bool collectVisible(int start, int eye, std::vector<int>& visible, std::vector<HorizonEdge>& horizon) {
    ++stamp_;
    visible = {start};
    faces_[start].mark = stamp_;
    for (std::size_t i = 0; i < visible.size(); ++i) {
      const Face& f = faces_[visible[i]];
      for (int k = 0; k < 3; ++k) {
        int g = f.adj[k];
        if (faces_[g].mark == stamp_) continue;
        if (dist(faces_[g], eye) > eps_) {
          faces_[g].mark = stamp_;
          visible.push_back(g);
        }
      }
    }
    for (int fi : visible)
      for (int k = 0; k < 3; ++k)
        if (faces_[faces_[fi].adj[k]].mark != stamp_)
          horizon.push_back({faces_[fi].v[k], faces_[fi].v[(k + 1) % 3], faces_[fi].adj[k]});
    // A horizon that is not one simple loop means the tolerance let an inconsistent set through.
    for (std::size_t i = 0; i < horizon.size(); ++i)
      for (std::size_t j = i + 1; j < horizon.size(); ++j)
        if (horizon[i].a == horizon[j].a) return false;
    return horizon.size() >= 3;
  }

  void addFarthest(int f) {
    auto& out = faces_[f].outside;
    auto it = std::max_element(out.begin(), out.end(),
                               [&](int i, int j) { return dist(faces_[f], i) < dist(faces_[f], j); });
    int eye = *it;
    std::vector<int> visible;
    std::vector<HorizonEdge> horizon;
    if (!collectVisible(f, eye, visible, horizon)) {
      out.erase(it);  // numerically ambiguous point: leave it out of the hull
      pending_.push_back(f);
      return;
    }
    std::vector<int> created = stitch(horizon, eye);
    reassignOutside(visible, created, eye);
  }

  std::vector<int> stitch(const std::vector<HorizonEdge>& horizon, int eye) {
    std::vector<int> created;
    for (const auto& e : horizon) {
      int nf = makeFace(e.a, e.b, eye);
      faces_[nf].adj[0] = e.neighbour;
      Face& nb = faces_[e.neighbour];
      for (int k = 0; k < 3; ++k)
        if (nb.v[k] == e.b && nb.v[(k + 1) % 3] == e.a) nb.adj[k] = nf;
      created.push_back(nf);
    }
    // New face (a, b, eye): across (b, eye) is the new face starting at b; across (eye, a) the one ending at a.
    for (std::size_t i = 0; i < created.size(); ++i)
      for (std::size_t j = 0; j < created.size(); ++j) {
        if (horizon[j].a == horizon[i].b) faces_[created[i]].adj[1] = created[j];
        if (horizon[j].b == horizon[i].a) faces_[created[i]].adj[2] = created[j];
      }
    return created;
  }

  void reassignOutside(const std::vector<int>& visible, const std::vector<int>& created, int eye) {
    for (int fi : visible) {
      faces_[fi].alive = false;
      for (int i : faces_[fi].outside) {
        if (i == eye) continue;
        for (int nf : created)
          if (dist(faces_[nf], i) > eps_) {
            faces_[nf].outside.push_back(i);
            break;
          }
      }
      std::vector<int>().swap(faces_[fi].outside);
    }
    for (int nf : created)
      if (!faces_[nf].outside.empty()) pending_.push_back(nf);
  }

  std::span<const glm::dvec3> p_;
  double eps_;
  std::vector<Face> faces_;
  std::vector<int> pending_;
  int stamp_ = 0;
};
}  // namespace

std::vector<glm::uvec3> convexHull(std::span<const glm::dvec3> points) {
  if (points.size() < 4) return {};
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  double scale = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(scale > 0.0) || !std::isfinite(scale)) return {};
  return Quickhull(points, 1e-11 * scale).run();
}
}  // namespace hp
