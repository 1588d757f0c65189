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

// Gravity plus a backward pull that grows toward the forehead: combs hair away from the face
// (turning a forehead strand straight toward gravity would take it over the face).
glm::vec3 combDirection(const glm::vec3& normal, const glm::vec3& gravity) {
  float back = 0.3f + 4.0f * std::max(0.0f, normal.z);
  return glm::normalize(glm::normalize(gravity) + glm::vec3(0.0f, 0.0f, -back));
}
}  // namespace

GrowthOptions defaultHeadGrowth() {
  GrowthOptions g;
  g.length = 0.30f;
  g.lengthVariation = 0.15f;
  g.segmentRatio = 1.3f;
  g.bend = 0.35f;
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
  std::vector<glm::vec3> combs(scalp.vertexCount());
  for (std::uint32_t i = 0; i < combs.size(); ++i) combs[i] = combDirection(scalp.normals[i], growth.bendDirection);
  HairAsset asset;
  asset.name = "default head";
  asset.colliders = defaultHeadColliders();
  asset.guides = growGuides(scalp, growth, asset.colliders, combs);
  asset.topology = buildInterpolationTopology(asset.guides.roots(), scalp.triangles, density);
  asset.head = makeDefaultHeadMesh();
  return asset;
}
}  // namespace hp
