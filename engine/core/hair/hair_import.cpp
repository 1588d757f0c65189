#include "engine/core/hair/hair_import.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/parted_triangles.h"
#include "engine/core/hair/segment_profile.h"

namespace hp {
namespace {
// `placed`: the data's points in head space.
GuideSet keepAsIs(const HairFileData& data, std::vector<glm::vec3> placed, const std::string& source) {
  const std::uint32_t P = data.strandPointCount(0);
  for (std::uint32_t s = 1; s < data.strandCount; ++s)
    if (data.strandPointCount(s) != P)
      throw Error(source + ": keeping strands as they are needs one point count for all strands; strand 0 has " +
                  std::to_string(P) + ", strand " + std::to_string(s) + " has " +
                  std::to_string(data.strandPointCount(s)));
  checkParticlesPerGuide(P, source.c_str());
  GuideSet guides;
  guides.particlesPerGuide = P;
  guides.positions = std::move(placed);
  return guides;
}

HeadMesh collidersMesh(const std::vector<SphereCollider>& colliders) {
  HeadMesh mesh;
  for (const auto& c : colliders) appendMesh(mesh, makeEllipsoidMesh(c.center, glm::vec3(c.radius * 0.98f)));
  return mesh;
}
}  // namespace

// The least-squares sphere runs through the middle of the roots: on a scalp that is not a sphere about half
// of them lie inside it, and the pearls next to those roots, pushed out of it, flung their strands up on the
// first frames. So the fit keeps its centre and shrinks to the nearest root: every root on or outside it. It
// shrinks to half its size at most: a root far inside (a bun's tie, a stray strand) says little of the head.
SphereCollider colliderUnderRoots(const SphereCollider& fit, std::span<const glm::vec3> roots) {
  SphereCollider sphere = fit;
  const float floor = 0.5f * sphere.radius;
  for (const glm::vec3& root : roots) sphere.radius = std::min(sphere.radius, glm::distance(root, sphere.center));
  sphere.radius = std::max(sphere.radius, floor);
  return sphere;
}

GuideSet guidesFromHair(const HairFileData& data, const HairImportOptions& options, const std::string& source) {
  validateHairData(data, source);
  options.transform.validate();
  // Placed first (the transform is a similarity: it commutes with resampling), and checked before resampling
  // squares their distances.
  std::vector<glm::vec3> placed(data.points.size());
  std::transform(data.points.begin(), data.points.end(), placed.begin(),
                 [&](const glm::vec3& p) { return options.transform.applyToPoint(p); });
  checkHeadSpaceExtent(placed, source);
  if (options.keepStrands) return keepAsIs(data, std::move(placed), source);
  checkParticlesPerGuide(options.particlesPerGuide, source.c_str());
  const std::uint32_t P = options.particlesPerGuide;
  GuideSet guides;
  guides.particlesPerGuide = P;
  guides.positions.resize(std::size_t(data.strandCount) * P);
  std::uint32_t offset = 0;
  for (std::uint32_t s = 0; s < data.strandCount; ++s) {
    std::uint32_t n = data.strandPointCount(s);
    auto out = guides.guide(s);
    resamplePolyline({placed.data() + offset, n}, P, options.segmentRatio, out);
    offset += n;
  }
  return guides;
}

namespace {
// The head's size the parting margin scales with. With a distance grid in the body (a mesh, not a sphere) the
// sphere under the roots; with spheres only, the one whose surface lies nearest the roots on average (the head
// they grow on: not an ear's small sphere, which would make the margin smaller than the sagitta of
// neighbouring guides, nor a torso's large one).
float headRadius(const std::vector<glm::vec3>& roots, const CollisionBody& body) {
  if (body.grid != nullptr || body.spheres.empty()) return colliderUnderRoots(fitSphere(roots).sphere, roots).radius;
  float radius = body.spheres.front().radius;
  double nearestGap = INFINITY;
  for (const SphereCollider& s : body.spheres) {
    double gap = 0.0;
    for (const glm::vec3& r : roots) gap += std::abs(double(glm::distance(r, s.center)) - double(s.radius));
    if (gap < nearestGap) nearestGap = gap, radius = s.radius;
  }
  return radius;
}

// Dropped whatever the density: a model drawing its own strands blends nothing now, but its triangles are the
// ones any later density blends over (Asset::withDensity). Every triangle parted is refused in any mode: the
// body does not fit the model.
PartedTriangles dropParted(const GuideSet& guides, std::vector<glm::uvec3> triangles, const CollisionBody& body,
                           const std::string& name) {
  if (body.empty() || triangles.empty()) return {std::move(triangles), 0};
  const float margin = kPartedMargin * headRadius(guides.roots(), body);
  PartedTriangles scalp = dropPartedTriangles(guides, triangles, body, margin);
  if (scalp.kept.empty())
    throw Error(name + ": every one of its " + std::to_string(triangles.size()) + " root triangles has guides "
                "parting around the body the hair collides with (strands blended from them would run through it): "
                "check the colliders or the character mesh against the model's units and place");
  return scalp;
}
}  // namespace

HairAsset assembleImportedAsset(GuideSet guides, std::vector<glm::uvec3> triangles,
                                const HairImportOptions& options, std::string name) {
  HairAsset asset;
  asset.name = std::move(name);
  asset.colliders = options.colliders.value_or(std::vector<SphereCollider>{});
  PartedTriangles scalp =
      dropParted(guides, std::move(triangles), CollisionBody{asset.colliders, options.collisionGrid.get()}, asset.name);
  asset.partedTriangles = scalp.dropped;
  asset.topology = buildInterpolationTopology(guides.roots(), std::move(scalp.kept), options.density);
  asset.guides = std::move(guides);
  asset.fittedCollider = options.collidersFitted;
  if (!asset.fittedCollider) asset.head = collidersMesh(asset.colliders);
  return asset;
}

HairAsset importHairAsset(const HairFileData& data, const HairImportOptions& options, const std::string& source) {
  GuideSet guides = guidesFromHair(data, options, source);
  std::vector<glm::vec3> roots = guides.roots();
  SphereFit fit = fitSphere(roots);
  RootTriangulation tri = triangulateRoots(roots, fit.sphere.center, options.triangulation);
  if (tri.triangles.empty())
    throw Error(source + ": cannot triangulate the strand roots (too few, or all on one line or circle)");
  HairImportOptions fitted = options;
  if (!fitted.colliders) fitted.colliders = {{colliderUnderRoots(fit.sphere, roots)}}, fitted.collidersFitted = true;
  return assembleImportedAsset(std::move(guides), std::move(tri.triangles), fitted, source);
}
}  // namespace hp
