#include "engine/hair/default_head.h"

#include <cmath>

#include "engine/hair/convex_hull.h"
#include "engine/hair/head_mesh.h"

namespace hp {
namespace {
const glm::vec3 kCraniumRadii{0.088f, 0.098f, 0.098f};  // inside the 0.1 m cranium collider

struct Part {
  SphereCollider collider;
  glm::vec3 renderRadii;  // each <= collider.radius
};

const Part kParts[] = {
    {{{0.0f, 0.0f, 0.0f}, 0.100f}, kCraniumRadii},                 // cranium
    {{{0.0f, -0.055f, 0.025f}, 0.068f}, {0.062f, 0.068f, 0.066f}},  // face and jaw
    {{{0.0f, -0.140f, -0.010f}, 0.055f}, {0.048f, 0.055f, 0.050f}}, // neck, upper
    {{{0.0f, -0.190f, -0.010f}, 0.055f}, {0.050f, 0.055f, 0.050f}}, // neck, lower
    {{{0.0f, -0.280f, -0.010f}, 0.100f}, {0.100f, 0.070f, 0.080f}}, // upper back and chest
    {{{0.120f, -0.260f, -0.010f}, 0.090f}, {0.090f, 0.055f, 0.075f}},  // right shoulder
    {{{-0.120f, -0.260f, -0.010f}, 0.090f}, {0.090f, 0.055f, 0.075f}}, // left shoulder
};

// Hairline: a tilted plane through the unit sphere, high at the forehead (+Z), low at the nape.
bool onScalp(const glm::dvec3& u) { return u.y > -0.1 + 0.6 * u.z; }

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

// Near the cranium hair lies along it: turn toward the downhill tangent (gravity minus its normal
// part, plus a slight pull inward that the collider turns into sliding), with a backward comb that
// grows toward the forehead so no strand falls over the face. Away from the head: plain gravity.
glm::vec3 combDirection(const glm::vec3& position, const glm::vec3& gravity) {
  const SphereCollider& cranium = kParts[0].collider;
  glm::vec3 offset = position - cranium.center;
  float distance = glm::length(offset);
  glm::vec3 down = glm::normalize(gravity);
  if (distance > cranium.radius * 1.3f || offset.y < -0.02f) return down;
  glm::vec3 n = offset / distance;
  glm::vec3 pull = down + glm::vec3(0.0f, 0.0f, -(0.3f + 3.0f * std::max(0.0f, n.z)));
  glm::vec3 tangent = pull - glm::dot(pull, n) * n;
  if (glm::length(tangent) < 1e-4f) tangent = glm::vec3(0.0f, 0.0f, -1.0f);
  return glm::normalize(tangent) - 0.2f * n;
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
  std::vector<glm::dvec3> dirs = fibonacciSphere(sphereSamples);
  std::vector<std::int64_t> remap(dirs.size(), -1);
  std::vector<glm::vec3> positions, normals;
  std::vector<glm::uvec3> triangles;
  auto vertex = [&](std::uint32_t i) {
    if (remap[i] < 0) {
      remap[i] = static_cast<std::int64_t>(positions.size());
      glm::vec3 u(dirs[i]);
      positions.push_back(u * kCraniumRadii);
      normals.push_back(glm::normalize(u / kCraniumRadii));
    }
    return static_cast<std::uint32_t>(remap[i]);
  };
  for (const auto& t : convexHull(dirs))
    if (onScalp(dirs[t.x]) && onScalp(dirs[t.y]) && onScalp(dirs[t.z]))
      triangles.emplace_back(vertex(t.x), vertex(t.y), vertex(t.z));
  return buildScalpMesh(std::move(positions), std::move(triangles), std::move(normals), "default scalp");
}

std::vector<SphereCollider> defaultHeadColliders() {
  std::vector<SphereCollider> out;
  for (const auto& part : kParts) out.push_back(part.collider);
  return out;
}

HeadMesh makeDefaultHeadMesh() {
  HeadMesh mesh;
  for (const auto& part : kParts) appendMesh(mesh, makeEllipsoidMesh(part.collider.center, part.renderRadii));
  return mesh;
}

HairAsset buildDefaultHeadAsset(const GrowthOptions& growth, const DensityOptions& density) {
  growth.validate();
  ScalpMesh scalp = makeDefaultScalp();
  HairAsset asset;
  asset.name = "default head";
  asset.colliders = defaultHeadColliders();
  auto comb = [&](const glm::vec3& p, std::uint32_t) { return combDirection(p, growth.bendDirection); };
  asset.guides = growGuides(scalp, growth, asset.colliders, comb);
  asset.topology = buildInterpolationTopology(asset.guides.roots(), scalp.triangles, density);
  asset.head = makeDefaultHeadMesh();
  markScalp(asset.head, asset.guides.roots());
  return asset;
}
}  // namespace hp
