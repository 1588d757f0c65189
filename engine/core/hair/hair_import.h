#pragma once
// Contract: turns a .hair model into a HairAsset. Every strand becomes a guide: resampled to
// particlesPerGuide points with root-increasing spacing (segmentRatio), or kept as is when
// keepStrands is set (then every strand must have the same point count, in [2, 64]). Points map into
// head space through `transform`. Roots are triangulated (triangulateRoots) around a sphere fitted to
// them; that sphere, shrunk under every root (colliderUnderRoots), is also the head collider unless
// `colliders` gives the colliders explicitly; a given collider is drawn as the head, one sphere slightly inside
// each. Throws hp::Error naming `source`.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/hair/collider.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/model_transform.h"
#include "engine/core/hair/root_topology.h"
#include "engine/core/hair/sdf_grid.h"
#include "engine/core/hair/strand_topology.h"

namespace hp {
struct HairImportOptions {
  ModelTransform transform;
  bool keepStrands = false;
  std::uint32_t particlesPerGuide = kDefaultParticlesPerGuide;
  float segmentRatio = 1.3f;
  RootTriangulationOptions triangulation;
  DensityOptions density;
  std::optional<std::vector<SphereCollider>> colliders;  // empty optional: fit one under the roots
  bool collidersFitted = false;  // `colliders` were fitted by the importer, not given (collide, draw no head)
  // The distance grid the hair will also collide with (scene collider meshes, or a character mesh that takes
  // the colliders' place): the parting test looks at it with `colliders`. The asset does not keep it.
  std::shared_ptr<const SdfGrid> collisionGrid;
};

// The head collider fitted to imported roots: the roots' least-squares sphere `fit`, shrunk to the nearest
// root (to half its radius at most), so no root starts inside it.
SphereCollider colliderUnderRoots(const SphereCollider& fit, std::span<const glm::vec3> roots);

GuideSet guidesFromHair(const HairFileData& data, const HairImportOptions& options, const std::string& source);

// Builds topology, colliders and head mesh around existing guides (shared by .hair and .obj imports; each
// passes its colliders: given, or fitted by the caller). Given colliders are drawn as the head; fitted ones
// (`collidersFitted`) only collide (a sphere fitted to a strip of roots is a poor guess that would hide the
// hair it was fitted to): the asset has no head mesh and fittedCollider set. Root triangles whose guides part
// around the colliders and `collisionGrid` are dropped (parted_triangles.h; refused when every one is), whatever
// the density: one that draws the guides themselves blends nothing, but a later one may.
HairAsset assembleImportedAsset(GuideSet guides, std::vector<glm::uvec3> triangles,
                                const HairImportOptions& options, std::string name);

HairAsset importHairAsset(const HairFileData& data, const HairImportOptions& options, const std::string& source);
}  // namespace hp
