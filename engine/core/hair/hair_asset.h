#pragma once
// Contract: everything the GPU side needs to simulate and draw one head of hair, in head space:
// guides (P particles each, root first, the rest pose), the interpolation topology (triangles of
// guide indices and one binding per render strand), sphere colliders, an optional signed distance
// grid the hair is kept outside of (the default head's field, or one built from collider meshes),
// and an opaque head mesh to draw. Host-only data; nothing here touches Vulkan. Produced by buildDefaultHeadAsset,
// buildSceneAsset or the importers.
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/collider.h"
#include "engine/core/hair/root_binding.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/sdf_grid.h"
#include "engine/core/hair/strand_topology.h"

namespace hp {
struct HeadMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // unit, one per position
  std::vector<std::uint32_t> indices;  // triangle list, counter-clockwise seen from outside
  // Per position, 1 where hair grows (the scalp shows through as hair colour), 0 on bare skin;
  // empty means bare everywhere. Filled by markScalp (engine/core/hair/head_mesh.h).
  std::vector<float> scalp;
};

struct HairAsset {
  std::string name;
  GuideSet guides;
  InterpolationTopology topology;
  std::vector<SphereCollider> colliders;
  std::shared_ptr<const SdfGrid> sdf;  // null: no distance-field collider (shared: grids are large)
  HeadMesh head;
  // The colliders were fitted to the roots by an importer, not given: they collide but are not drawn (head
  // is empty), and tools say so.
  bool fittedCollider = false;
  // Scalp triangles an importer dropped because their guides part around the head (parted_triangles.h).
  std::uint32_t partedTriangles = 0;
  // A character mesh given with the model (null: none): drawn as the head, the distance grid the hair
  // collides with (unless the scene gives colliders), and the surface the guides' roots bind to.
  std::shared_ptr<const CharacterMesh> character;
  bool characterCollides = false;  // `sdf` is the character's grid (no scene colliders replaced it)
  RootBindings rootBindings;  // one per guide on `character` (empty without one)
};
}  // namespace hp
