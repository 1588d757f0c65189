// Scene -> HairAsset: dispatch on the model kind, then apply the scene's overrides.
#include "engine/error.h"
#include "engine/hair/default_head.h"
#include "engine/hair/head_mesh.h"
#include "engine/hair/fit_sphere.h"
#include "engine/hair/hair_import.h"
#include "engine/hair/obj_import.h"
#include "engine/hair/scene.h"

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

// An OBJ scalp grows guides; without scene colliders a sphere fitted to the scalp keeps hair out.
HairAsset objAsset(const Scene& scene) {
  ScalpMesh scalp = loadObjScalp(scene.model.path, scene.model.transform);
  HairImportOptions o = importOptions(scene);
  if (!o.colliders) {
    SphereCollider fitted = fitSphere(scalp.positions).sphere;
    o.colliders = std::vector<SphereCollider>{fitted};
  }
  GuideSet guides = growGuides(scalp, scene.growth, *o.colliders);
  return assembleImportedAsset(std::move(guides), scalp.triangles, o, scene.model.path.string());
}
}  // namespace

namespace {
HairAsset modelAsset(const Scene& scene) {
  switch (scene.model.kind) {
    case ModelSpec::Kind::Hair:
      return importHairAsset(readHairFile(scene.model.path), importOptions(scene), scene.model.path.string());
    case ModelSpec::Kind::Obj:
      return objAsset(scene);
    case ModelSpec::Kind::Default:
      break;
  }
  HairAsset asset = buildDefaultHeadAsset(scene.growth, scene.density);
  if (scene.colliders) asset.colliders = *scene.colliders;
  return asset;
}
}  // namespace

HairAsset buildSceneAsset(const Scene& scene) {
  HairAsset asset = modelAsset(scene);
  if (asset.head.scalp.empty()) markScalp(asset.head, asset.guides.roots());
  return asset;
}
}  // namespace hp
