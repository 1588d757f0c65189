#include "engine/core/hair/default_head.h"

#include <cmath>

#include "engine/core/hair/convex_hull.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/head_sdf.h"
#include "engine/core/hair/level_set_mesh.h"
#include "engine/core/hair/mesh_simplify_cache.h"
#include "engine/core/hair/parallel_for.h"

namespace hp {
namespace {
// Evenly spread directions (Fibonacci sphere), deterministic.
std::vector<glm::dvec3> fibonacciSphere(std::uint32_t n) {
  std::vector<glm::dvec3> dirs(n);
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (std::uint32_t i = 0; i < n; ++i) {
    double y = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - y * y);
    dirs[i] = {r * std::sin(golden * i), y, r * std::cos(golden * i)};
  }
  return dirs;
}

constexpr float kPartX = 0.012f;  // the side parting runs front to back at this x, on the crown
// The one test of which side of the parting a root is on (the comb and the dropped triangles agree).
bool rightOfPart(const glm::vec3& root) { return root.x >= kPartX; }

// Hair on either side of the parting falls to opposite sides, so no render strand may be interpolated
// across it (it would cut through the head): scalp triangles on the crown that straddle it are dropped.
bool straddlesPart(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const bool top = a.y > 0.0f && b.y > 0.0f && c.y > 0.0f;
  const bool left = !rightOfPart(a) || !rightOfPart(b) || !rightOfPart(c);
  const bool right = rightOfPart(a) || rightOfPart(b) || rightOfPart(c);
  return top && left && right;
}

// Near the head hair lies along it: the downhill tangent of gravity plus, on the cranium, a push away
// from the parting and backward (strongest at the forehead and the temples) so it falls behind the
// ears and shoulders, never over the face. A slight pull into the head makes the growth slide along
// the field. Away from the head: gravity, slightly backward. The side of the parting is the root's
// (`root`), not the growing point's: a guide rooted beside the parting whose growth drifts across it
// would otherwise turn to the far side, and strands interpolated between it and its neighbours would
// cut through the skull.
glm::vec3 combDirection(const glm::vec3& p, const glm::vec3& root, const glm::vec3& gravity) {
  const glm::vec3 down = glm::normalize(gravity);
  const glm::vec3 back(0.0f, 0.0f, -1.0f);
  if (headDistance(p) > 0.025f) return glm::normalize(down + 0.3f * back);
  const glm::vec3 n = glm::normalize(headGradient(p));
  glm::vec3 pull = down + back * (0.5f + 3.0f * std::max(0.0f, n.z));
  if (p.y > -0.02f) pull += glm::vec3(rightOfPart(root) ? 1.0f : -1.0f, 0.0f, 0.0f) * 1.5f * std::max(0.0f, n.y);
  glm::vec3 tangent = pull - glm::dot(pull, n) * n;
  if (glm::length(tangent) < 1e-4f) tangent = back;
  return glm::normalize(tangent) - 0.2f * n;
}

struct Geometry {
  std::shared_ptr<const SdfGrid> grid;
  ScalpMesh scalp;
  HeadMesh mesh;  // scalp marked
};

const Geometry& geometry() {
  static const Geometry g = [] {
    Geometry out;
    NarrowBandGrid field = makeDefaultHeadField();
    out.scalp = makeDefaultScalp();
    out.mesh = makeDefaultHeadMesh(field);
    markScalp(out.mesh, out.scalp.positions);
    out.mesh = simplifyDefaultHeadMesh(out.mesh);
    out.grid = std::make_shared<SdfGrid>(std::move(field.grid));
    return out;
  }();
  return g;
}
}  // namespace

GrowthOptions defaultHeadGrowth() {
  GrowthOptions g;
  g.length = 0.30f;
  g.lengthVariation = 0.15f;
  g.segmentRatio = 1.4f;  // short first segments: hair leaves the scalp low
  g.bend = 0.6f;
  g.seed = 1;
  return g;
}

ScalpMesh makeDefaultScalp(std::uint32_t sphereSamples) {
  const std::vector<glm::dvec3> dirs = fibonacciSphere(sphereSamples);
  // Every direction above the hairline meets the surface (on threads: each ray is independent); the
  // mesh keeps those that a scalp triangle uses, numbered in the order the triangles first use them.
  std::vector<std::uint8_t> onScalp(dirs.size());
  std::vector<glm::vec3> rays;  // the directions above the hairline, in order
  std::vector<std::uint32_t> ray(dirs.size(), 0);
  for (std::size_t i = 0; i < dirs.size(); ++i)
    if ((onScalp[i] = aboveHairline(glm::vec3(dirs[i])))) ray[i] = std::uint32_t(rays.size()), rays.push_back(glm::vec3(dirs[i]));
  std::vector<glm::vec3> surface(rays.size()), gradient(rays.size());
  constexpr std::size_t kChunk = 256;  // rays per batch
  parallelFor((rays.size() + kChunk - 1) / kChunk, [&](std::size_t c) {
    const std::size_t first = c * kChunk, n = std::min(kChunk, rays.size() - first);
    headSurfacesAlong(std::span(rays).subspan(first, n), std::span(surface).subspan(first, n),
                      std::span(gradient).subspan(first, n));
  }, 1);
  std::vector<std::int64_t> remap(dirs.size(), -1);
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::uvec3> triangles;
  auto vertex = [&](std::uint32_t i) {
    if (remap[i] < 0) {
      remap[i] = static_cast<std::int64_t>(positions.size());
      positions.push_back(surface[ray[i]]);
      normals.push_back(glm::normalize(gradient[ray[i]]));
    }
    return static_cast<std::uint32_t>(remap[i]);
  };
  for (const auto& t : convexHull(dirs)) {
    if (!onScalp[t.x] || !onScalp[t.y] || !onScalp[t.z]) continue;
    const glm::uvec3 tri(vertex(t.x), vertex(t.y), vertex(t.z));
    if (!straddlesPart(positions[tri.x], positions[tri.y], positions[tri.z])) triangles.push_back(tri);
  }
  return buildScalpMesh(std::move(positions), std::move(triangles), std::move(normals), "default scalp");
}

NarrowBandGrid makeDefaultHeadField() {
  return sampleNarrowBand(headField(), kHeadFieldLow, kHeadFieldHigh, kDefaultHeadCell, kDefaultHeadBand,
                          kDefaultHeadBrick);
}

HeadMesh makeDefaultHeadMesh(const NarrowBandGrid& field) {
  return meshZeroLevel(field.grid, field.band, kDefaultHeadMeshStride);
}

HeadMesh simplifyDefaultHeadMesh(const HeadMesh& marked) {
  return simplifyMeshCached(DiskCache::process(), marked, kDefaultHeadSimplify);
}

HairAsset buildDefaultHeadAsset(const GrowthOptions& growth, const DensityOptions& density) {
  growth.validate();
  const Geometry& geo = geometry();
  HairAsset asset;
  asset.name = "default head";
  asset.sdf = geo.grid;
  auto comb = [&](const glm::vec3& p, std::uint32_t guide) {
    return combDirection(p, geo.scalp.positions[guide], growth.bendDirection);
  };
  asset.guides = growGuides(geo.scalp, growth, {}, comb, headDistance);
  asset.topology = buildInterpolationTopology(asset.guides.roots(), geo.scalp.triangles, density);
  asset.head = geo.mesh;
  return asset;
}
}  // namespace hp
