#include "engine/core/hair/skin_transfer.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/parallel_for.h"
#include "engine/core/hair/rng.h"
#include "engine/core/hair/triangle_bvh.h"
#include "engine/core/shading/environment_sh.h"
#include "engine/core/shading/math_constants.h"
#include "shaders/shared/environment.h"

namespace hp {
namespace {
using Coefficients = std::array<float, 9>;
constexpr float kPi = float(shading::kPi);

// A ray's fate: the triangle and barycentrics it met on a front face, else `escaped` or a back face.
struct RayEnd {
  static constexpr std::uint32_t kEscaped = ~0u, kBackFace = ~0u - 1u;
  std::uint32_t triangle = kEscaped;
  float u = 0.0f, v = 0.0f;
};

// The top 24 bits of a hash (rng.h's pcgHash: a vertex's and a ray's jitter in the stratified grid) in [0, 1).
float unitFloat(std::uint32_t bits) { return float(bits >> 8) * (1.0f / 16777216.0f); }

// An orthonormal frame whose third axis is n (Duff et al. 2017). It turns about n by up to half a turn where
// n.z changes sign, so neighbours' frames are related by smoothTurned's twists, not taken as agreeing.
glm::mat3 tangentFrame(const glm::vec3& n) {
  const float sign = std::copysign(1.0f, n.z), a = -1.0f / (sign + n.z), b = n.x * n.y * a;
  return glm::mat3(glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x), glm::vec3(b, sign + n.y * n.y * a, -n.y), n);
}

// Coefficients seen in a frame's axes (frame: the frame's axes to the mesh's; its transpose back).
Coefficients turned(const Coefficients& c, const glm::mat3& frame) {
  EnvironmentSH sh{};
  for (std::size_t i = 0; i < c.size(); ++i) sh[i] = glm::dvec3(c[i], 0.0, 0.0);
  const EnvironmentSH out = rotateEnvironment(sh, glm::dmat3(frame));
  Coefficients r{};
  for (std::size_t i = 0; i < r.size(); ++i) r[i] = float(out[i].x);
  return r;
}

// Ray r of n from vertex v: cosine-distributed about n (Malley's method). The first sx x sy rays take one
// stratum each of an sx x sy grid (sx = floor(sqrt(count)), sy = count / sx), jittered within it; any
// rays left over are jittered over the whole square, so every direction keeps its share.
glm::vec3 rayDirection(const glm::vec3& n, std::uint32_t vertex, std::uint32_t r, std::uint32_t count) {
  const std::uint32_t sx = std::max(1u, std::uint32_t(std::sqrt(float(count)))), sy = count / sx;
  const std::uint32_t h = pcgHash(vertex * 1024u + r);
  const bool stratified = r < sx * sy;
  const float u1 = stratified ? (float(r % sx) + unitFloat(h)) / float(sx) : unitFloat(h);
  const float u2 = stratified ? (float(r / sx) + unitFloat(pcgHash(h))) / float(sy) : unitFloat(pcgHash(h));
  const float radius = std::sqrt(u1), phi = 2.0f * kPi * u2;
  const glm::mat3 frame = tangentFrame(n);
  return glm::normalize(frame * glm::vec3(radius * std::cos(phi), radius * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u1))));
}

// The clamped cosine about n in the basis: A_l Y_i(n), A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4 (the band
// factors of shared/environment.h, which are these over pi).
float cosineLobe(std::uint32_t i, const glm::vec3& n) {
  const float band = i == 0 ? gpu::ENV_COSINE_BAND0 : i < 4 ? gpu::ENV_COSINE_BAND1 : gpu::ENV_COSINE_BAND2;
  return kPi * band * gpu::envShBasis(i, n);
}

// Each vertex's neighbours along the mesh's edges (compressed rows, each neighbour once).
struct Neighbours {
  std::vector<std::uint32_t> start, list;
};
Neighbours meshNeighbours(std::size_t vertexCount, const std::vector<std::uint32_t>& indices) {
  std::vector<std::vector<std::uint32_t>> rows(vertexCount);
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3)
    for (int k = 0; k < 3; ++k) {
      rows[indices[t + k]].push_back(indices[t + (k + 1) % 3]);
      rows[indices[t + (k + 1) % 3]].push_back(indices[t + k]);
    }
  Neighbours n;
  n.start.reserve(vertexCount + 1);
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    n.start.push_back(static_cast<std::uint32_t>(n.list.size()));
    n.list.insert(n.list.end(), row.begin(), row.end());
  }
  n.start.push_back(static_cast<std::uint32_t>(n.list.size()));
  return n;
}

// `passes` times, every value becomes the mean of itself and its neighbours.
template <typename Value>
void smooth(std::vector<Value>& values, const Neighbours& nb, std::uint32_t passes) {
  std::vector<Value> next(values.size());
  for (std::uint32_t pass = 0; pass < passes; ++pass) {
    parallelFor(values.size(), [&](std::size_t v) {
      Value sum = values[v];
      for (std::uint32_t k = nb.start[v]; k < nb.start[v + 1]; ++k)
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += values[nb.list[k]][i];
      const float scale = 1.0f / float(1 + nb.start[v + 1] - nb.start[v]);
      for (float& c : sum) c *= scale;
      next[v] = sum;
    }, 1024);
    values.swap(next);
  }
}

bool usableNormal(const glm::vec3& n) { return std::abs(glm::length(n) - 1.0f) < 1e-3f; }

// Coefficients in a tangent frame turned about its normal (+z) by alpha: c'(w) = c(Rz(alpha) w). The m = +-1
// pairs (the x-like and y-like coefficients 3 and 1, 7 and 5) turn by alpha, the m = +-2 pair (8 and 4) by 2 alpha.
Coefficients turnedAboutNormal(const Coefficients& c, float alpha) {
  Coefficients r = c;
  const auto pair = [&](int cosine, int sine, float angle) {
    const float ca = std::cos(angle), sa = std::sin(angle);
    r[cosine] = c[cosine] * ca + c[sine] * sa;
    r[sine] = c[sine] * ca - c[cosine] * sa;
  };
  pair(3, 1, alpha);
  pair(7, 5, alpha);
  pair(8, 4, 2.0f * alpha);
  return r;
}

// The twist that carries neighbour u's tangent-frame coefficients into v's: the rotation taking n_v to n_u
// along the shortest arc carries v's frame to one about n_u, which u's frame turns by alpha about n_u (so
// that v's coefficients of u's function are turnedAboutNormal(u's, alpha)).
float twist(const glm::vec3& nv, const glm::vec3& nu) {
  const glm::mat3 fv = tangentFrame(nv), fu = tangentFrame(nu);
  const glm::vec3 axis = glm::cross(nv, nu);
  const float c = glm::dot(nv, nu);
  if (c < -0.999f) return 0.0f;  // opposite normals: no shortest arc (a fold; such a neighbour is rare)
  const glm::vec3 t = fv[0] * c + glm::cross(axis, fv[0]) + axis * (glm::dot(axis, fv[0]) / (1.0f + c));
  return std::atan2(glm::dot(fu[1], t), glm::dot(fu[0], t));
}

// `passes` times, every vertex's tangent-frame coefficients become the mean of its own and its neighbours',
// each neighbour's turned into its frame (twist); vertices without a usable normal neither change nor count.
void smoothTurned(std::vector<Coefficients>& values, const HeadMesh& mesh, const Neighbours& nb, std::uint32_t passes) {
  std::vector<float> twists(nb.list.size(), 0.0f);
  parallelFor(values.size(), [&](std::size_t v) {
    if (!usableNormal(mesh.normals[v])) return;
    for (std::uint32_t k = nb.start[v]; k < nb.start[v + 1]; ++k)
      if (usableNormal(mesh.normals[nb.list[k]])) twists[k] = twist(mesh.normals[v], mesh.normals[nb.list[k]]);
  }, 1024);
  std::vector<Coefficients> next(values.size());
  for (std::uint32_t pass = 0; pass < passes; ++pass) {
    parallelFor(values.size(), [&](std::size_t v) {
      Coefficients sum = values[v];
      std::uint32_t count = 1;
      if (usableNormal(mesh.normals[v]))
        for (std::uint32_t k = nb.start[v]; k < nb.start[v + 1]; ++k) {
          if (!usableNormal(mesh.normals[nb.list[k]])) continue;
          const Coefficients turned = turnedAboutNormal(values[nb.list[k]], twists[k]);
          for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += turned[i];
          ++count;
        }
      for (float& c : sum) c /= float(count);
      next[v] = sum;
    }, 1024);
    values.swap(next);
  }
}

// Casts every vertex's rays: the occluded part of its lobe, the share of rays that met the mesh, and where
// each ended.
void castRays(const HeadMesh& mesh, const TriangleBvh& bvh, std::uint32_t rays, float offset,
              std::vector<Coefficients>& occluded, std::vector<std::array<float, 1>>& blocked, std::vector<RayEnd>& ends) {
  parallelFor(mesh.positions.size(), [&](std::size_t v) {
    const glm::vec3 n = mesh.normals[v], origin = mesh.positions[v] + offset * n;
    occluded[v] = {};
    blocked[v][0] = 0.0f;
    if (!usableNormal(n)) return;  // no usable normal: nothing in the way (its rays stay escaped)
    Coefficients open{}, hidden{};  // the basis summed over the escaped and over the blocked rays
    std::uint32_t hits = 0;
    for (std::uint32_t r = 0; r < rays; ++r) {
      const glm::vec3 d = rayDirection(n, std::uint32_t(v), r, rays);
      const std::optional<TriangleBvh::Hit> hit = bvh.closestHit(origin, d, 0.0f, INFINITY);
      RayEnd& end = ends[v * rays + r];
      Coefficients& sum = hit ? hidden : open;
      for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i) sum[i] += gpu::envShBasis(i, d);
      if (!hit) continue;
      ++hits;
      end = hit->front ? RayEnd{hit->triangle, hit->u, hit->v} : RayEnd{RayEnd::kBackFace};
    }
    // Mostly open: the blocked rays' share (exact, 0, where nothing is in the way); mostly blocked: the lobe
    // less the escaped rays' share (exact where everything is). Either way the rays' noise scales with the
    // smaller part.
    const bool mostlyOpen = 2 * hits <= rays;
    for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i)
      occluded[v][i] = mostlyOpen ? hidden[i] * kPi / float(rays) : cosineLobe(i, n) - open[i] * kPi / float(rays);
    blocked[v][0] = float(hits) / float(rays);
  }, 256);
}

// The bounce transfer: per vertex the mean over its rays of the direct transfer where they met the mesh's
// front faces, but for the scalp under the hair (HeadMesh::scalp), whose light the hair over it takes; and
// the share of rays that met such reflecting skin.
void gatherBounce(const HeadMesh& mesh, const std::vector<Coefficients>& direct, const std::vector<RayEnd>& ends,
                  std::uint32_t rays, std::vector<Coefficients>& bounce, std::vector<std::array<float, 1>>& reflecting) {
  parallelFor(direct.size(), [&](std::size_t v) {
    Coefficients sum{};
    float share = 0.0f;
    for (std::uint32_t r = 0; r < rays; ++r) {
      const RayEnd& end = ends[v * rays + r];
      if (end.triangle >= RayEnd::kBackFace) continue;
      const std::uint32_t* corner = &mesh.indices[3 * std::size_t(end.triangle)];
      const float w[3] = {1.0f - end.u - end.v, end.u, end.v};
      for (int k = 0; k < 3; ++k) {
        const float lit = w[k] * (mesh.scalp.empty() ? 1.0f : 1.0f - mesh.scalp[corner[k]]);
        share += lit;
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += lit * direct[corner[k]][i];
      }
    }
    for (float& c : sum) c /= float(rays);
    bounce[v] = sum;
    reflecting[v][0] = share / float(rays);
  }, 1024);
}

float boxDiagonal(const std::vector<glm::vec3>& points) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return points.empty() ? 0.0f : glm::length(hi - lo);
}
}  // namespace

SkinTransfer computeSkinTransfer(const HeadMesh& mesh, const SkinTransferOptions& options) {
  if (options.raysPerVertex < 1 || options.raysPerVertex > 1024) throw Error("skin transfer: rays per vertex must be in [1, 1024]");
  if (options.smoothingPasses > 64) throw Error("skin transfer: smoothing passes must be in [0, 64]");
  if (mesh.normals.size() != mesh.positions.size()) throw Error("skin transfer: one normal per position is required");
  const TriangleBvh bvh(mesh.positions, mesh.indices);
  const std::uint32_t rays = options.raysPerVertex;
  const std::size_t count = mesh.positions.size();
  // Off the surface by a ten-thousandth of the model: past the float error of a hit on the vertex's own
  // triangles, far below any feature that shadows.
  const float offset = 1e-4f * boxDiagonal(mesh.positions);
  std::vector<Coefficients> occluded(count);
  std::vector<std::array<float, 1>> blocked(count), reflecting(count);
  std::vector<RayEnd> ends(count * rays);
  castRays(mesh, bvh, rays, offset, occluded, blocked, ends);
  const Neighbours nb = meshNeighbours(count, mesh.indices);
  // The occluded part is smoothed, not the direct transfer, so each vertex keeps its own normal's lobe; and it
  // is smoothed in each vertex's tangent frame (n along +z), each neighbour's carried into it along the edge,
  // so that neighbours facing other ways mix what they hide relative to their normals (a closed shell's
  // vertices all hide their whole lobe) and the result turns with the mesh.
  parallelFor(count, [&](std::size_t v) {
    if (usableNormal(mesh.normals[v])) occluded[v] = turned(occluded[v], tangentFrame(mesh.normals[v]));
  }, 256);
  smoothTurned(occluded, mesh, nb, options.smoothingPasses);
  parallelFor(count, [&](std::size_t v) {
    if (usableNormal(mesh.normals[v])) occluded[v] = turned(occluded[v], glm::transpose(tangentFrame(mesh.normals[v])));
  }, 256);
  smooth(blocked, nb, options.smoothingPasses);
  SkinTransfer out;
  out.direct.resize(count);
  for (std::size_t v = 0; v < count; ++v)
    for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i)
      out.direct[v][i] = (usableNormal(mesh.normals[v]) ? cosineLobe(i, mesh.normals[v]) : 0.0f) - occluded[v][i];
  out.bounce.resize(count);
  gatherBounce(mesh, out.direct, ends, rays, out.bounce, reflecting);
  smooth(out.bounce, nb, options.smoothingPasses);
  smooth(reflecting, nb, options.smoothingPasses);
  out.occluded = std::move(occluded);
  for (const auto& b : blocked) out.blocked.push_back(b[0]);
  for (const auto& r : reflecting) out.reflecting.push_back(r[0]);
  return out;
}
}  // namespace hp
