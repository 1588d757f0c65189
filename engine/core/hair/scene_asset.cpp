// Scene -> HairAsset: dispatch on the model kind, then apply the scene's overrides.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/mesh_file.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/scene.h"
#include "engine/core/hair/sdf_mesh.h"
#include "engine/core/hair/skeleton_pose.h"
#include "engine/core/hair/tfx_file.h"

namespace hp {
namespace {
HairImportOptions importOptions(const Scene& scene) {
  HairImportOptions o;
  o.transform = scene.model.transform;
  o.keepStrands = scene.model.keepStrands;
  o.particlesPerGuide = scene.growth.particlesPerGuide;
  o.segmentRatio = scene.growth.segmentRatio;
  o.density = scene.density;
  o.colliders = scene.colliders;
  return o;
}

// The scene's collider meshes, merged, as one distance grid (null when there are none).
std::shared_ptr<const SdfGrid> colliderGrid(const Scene& scene) {
  if (scene.colliderMeshes.empty()) return nullptr;
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
  float cell = 0.0f;
  for (const auto& m : scene.colliderMeshes) {
    const ScalpMesh mesh = loadObjScalp(m.path);
    const auto base = static_cast<std::uint32_t>(positions.size());
    positions.insert(positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (const auto& t : mesh.triangles) triangles.push_back(t + base);
    if (m.cell > 0.0f) cell = cell > 0.0f ? std::min(cell, m.cell) : m.cell;
  }
  try {
    return std::make_shared<SdfGrid>(meshSdf(positions, triangles, cell));
  } catch (const Error& e) {
    throw Error(scene.source + ": /colliders: " + e.what());
  }
}

// An OBJ scalp grows guides; without scene colliders a sphere fitted to the scalp keeps hair out of the head as
// it grows (the scalp is a surface: its fit is well posed, unlike a strip of hair roots'), and then collides and
// is drawn, unless a character mesh takes its place (`meshCollides`). `growthGrid` shapes the growth too
// (guides slide over it).
HairAsset objAsset(const Scene& scene, HairImportOptions o, bool meshCollides,
                   const std::shared_ptr<const SdfGrid>& growthGrid) {
  ScalpMesh scalp = loadObjScalp(scene.model.path, scene.model.transform);
  const std::vector<SphereCollider> spheres = o.colliders ? *o.colliders : std::vector{fitSphere(scalp.positions).sphere};
  DistanceFunction field;
  if (growthGrid) field = [&](const glm::vec3& p) { return growthGrid->sample(p); };
  GuideSet guides = growGuides(scalp, scene.growth, spheres, {}, field);
  o.colliders = meshCollides ? std::vector<SphereCollider>{} : spheres;
  return assembleImportedAsset(std::move(guides), scalp.triangles, o, scene.model.path.string());
}

// The body the model's hair collides with, as far as the import needs it: a character mesh that collides
// replaces every sphere (`meshCollides`), else the scene's colliders (spheres and `collisionGrid`, the grid of their meshes), else the
// model's own.
HairAsset modelAsset(const Scene& scene, bool meshCollides, const std::shared_ptr<const SdfGrid>& collisionGrid,
                     const std::shared_ptr<const SdfGrid>& growthGrid) {
  HairImportOptions o = importOptions(scene);
  o.collisionGrid = collisionGrid;
  if (scene.model.kind == ModelSpec::Kind::Obj) return objAsset(scene, o, meshCollides, growthGrid);
  if (meshCollides) o.colliders.emplace();  // no sphere fitted under the roots: the mesh takes its place
  switch (scene.model.kind) {
    case ModelSpec::Kind::Hair:
      return importHairAsset(readHairFile(scene.model.path), o, scene.model.path.string());
    case ModelSpec::Kind::Tfx:
      return importHairAsset(tfxToHair(readTfxFile(scene.model.path)), o, scene.model.path.string());
    case ModelSpec::Kind::Obj:
    case ModelSpec::Kind::Default:
      break;
  }
  return buildDefaultHeadAsset(scene.growth, scene.density);
}
}  // namespace

namespace {
struct CharacterParts {
  std::shared_ptr<const CharacterMesh> mesh;
  std::shared_ptr<const SdfGrid> grid;
  float diagonal = 0.0f;  // of the mesh's rest box
};

// How far a skinned mesh's clips take its vertices past its rest box [lo, hi]: each clip at up to 33 times,
// fewer when the clips and vertices are many (at most 2^27 skinned vertices in all).
float clipReach(const CharacterMesh& m, const glm::vec3& lo, const glm::vec3& hi) {
  if (m.animations.empty()) return 0.0f;
  const std::uint64_t perSample = std::uint64_t(m.animations.size()) * std::max<std::size_t>(m.positions.size(), 1);
  const int steps = int(std::clamp<std::uint64_t>((std::uint64_t(1) << 27) / perSample, 2, 33)) - 1;
  float reach = 0.0f;
  for (const AnimationClip& clip : m.animations)
    for (int k = 0; k <= steps; ++k) {
      const SkinnedVertices posed = skinMesh(m, skinningMatrices(m, samplePose(m, clip, clip.duration * float(k) / float(steps))));
      for (const glm::vec3& p : posed.positions) {
        const glm::vec3 out = glm::max(lo - p, p - hi);
        const float far = std::max(out.x, std::max(out.y, out.z));
        reach = std::isfinite(far) ? std::max(reach, far) : INFINITY;  // refused by the caller
      }
    }
  return reach;
}

CharacterParts loadCharacter(const Scene& scene) {
  if (scene.model.kind == ModelSpec::Kind::Default)
    throw Error(scene.source + ": a character mesh needs a model file (.hair, .tfx or .obj), not the default head");
  CharacterParts parts;
  parts.mesh = std::make_shared<const CharacterMesh>(loadCharacterMesh(scene.mesh->path, scene.model.transform));
  const CharacterMesh& m = *parts.mesh;
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const float longest = std::max(hi.x - lo.x, std::max(hi.y - lo.y, hi.z - lo.z));
  parts.diagonal = glm::length(hi - lo);
  const float cell = scene.mesh->cell > 0.0f ? scene.mesh->cell : longest / 128.0f;
  const float reach = clipReach(m, lo, hi);  // a skinned mesh's clips may take it past its rest box
  if (!(reach <= 16.0f * longest))
    throw Error(m.source + ": its animation clips move it more than 16 times its own size from its rest pose");
  try {
    parts.grid = std::make_shared<SdfGrid>(meshSdf(m.positions, m.triangles, cell, 4 + std::uint32_t(std::ceil(reach / cell))));
  } catch (const Error& e) {
    throw Error(m.source + ": its distance grid: " + e.what());
  }
  return parts;
}

// The mesh becomes the drawn head and (without scene colliders) the only collider; the roots bind to it.
// Roots more than 2% of the mesh's diagonal from it are counted as far.
void attachCharacter(HairAsset& asset, const CharacterParts& character, bool collide) {
  const CharacterMesh& m = *character.mesh;
  asset.head = HeadMesh{};
  asset.head.positions = m.positions;
  asset.head.normals = m.normals;
  for (const auto& t : m.triangles) asset.head.indices.insert(asset.head.indices.end(), {t.x, t.y, t.z});
  if (collide) {
    asset.colliders.clear();
    asset.sdf = character.grid;
    asset.fittedCollider = false;
    asset.characterCollides = true;
  }
  asset.rootBindings = bindRoots(asset.guides.roots(), m.positions, m.triangles, 0.02f * character.diagonal);
  asset.character = character.mesh;
}
}  // namespace

std::optional<ModelSpec::Kind> modelKindOf(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".hair") return ModelSpec::Kind::Hair;
  if (ext == ".tfx") return ModelSpec::Kind::Tfx;
  if (ext == ".obj") return ModelSpec::Kind::Obj;
  return std::nullopt;
}

Scene::Scene() : growth(defaultHeadGrowth()) {}

HairAsset buildSceneAsset(const Scene& scene) {
  const std::shared_ptr<const SdfGrid> grid = colliderGrid(scene);
  CharacterParts character;
  if (scene.mesh) character = loadCharacter(scene);
  const bool meshCollides = scene.mesh && !scene.colliders;
  HairAsset asset = modelAsset(scene, meshCollides, meshCollides ? character.grid : grid, grid ? grid : character.grid);
  if (scene.colliders) {
    asset.colliders = *scene.colliders;
    asset.sdf = grid;
  }
  if (scene.mesh) attachCharacter(asset, character, !scene.colliders);
  if (asset.head.scalp.empty()) markScalp(asset.head, asset.guides.roots());
  return asset;
}
}  // namespace hp
