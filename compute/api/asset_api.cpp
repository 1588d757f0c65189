// hairpipe::Asset, loadAsset and defaultHeadAsset over the core's importers and the default head.
#include <cmath>
#include <optional>

#include "compute/api/access.h"
#include "compute/api/convert.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/mesh_file.h"
#include "engine/core/hair/root_binding.h"
#include "engine/core/hair/skeleton_pose.h"
#include "engine/core/hair/scene.h"
#include "engine/core/hair/strand_topology.h"

namespace hairpipe {

// A moved-from Asset counts nothing and has no name.
std::uint32_t Asset::guideCount() const noexcept { return impl_ ? impl_->guides.guideCount() : 0; }
std::uint32_t Asset::particlesPerGuide() const noexcept { return impl_ ? impl_->guides.particlesPerGuide : 0; }
std::uint32_t Asset::strandCount() const noexcept {
  return impl_ ? static_cast<std::uint32_t>(impl_->topology.strands.size()) : 0;
}
std::uint32_t Asset::headTriangleCount() const noexcept {
  return impl_ ? static_cast<std::uint32_t>(impl_->head.indices.size() / 3) : 0;
}
std::uint32_t Asset::bareScalpTriangleCount() const noexcept { return impl_ ? impl_->partedTriangles : 0; }
Result<std::vector<Vec3>> Asset::guideRoots() const noexcept {
  return guarded<std::vector<Vec3>>("hairpipe::Asset::guideRoots", [&] {
    std::vector<Vec3> out;
    for (const glm::vec3& r : Access::asset(*this).guides.roots()) out.push_back({r.x, r.y, r.z});
    return out;
  });
}
const char* Asset::name() const noexcept { return impl_ ? impl_->name.c_str() : ""; }

Result<CharacterInfo> Asset::character() const noexcept {
  return guarded<CharacterInfo>("hairpipe::Asset::character", [&] {
    const hp::HairAsset& a = Access::asset(*this);
    if (!a.character) throw hp::Error(a.name + " was loaded without a character mesh (AssetSource::mesh)");
    const hp::CharacterMesh& m = *a.character;
    CharacterInfo info;
    info.vertices = m.vertexCount();
    info.triangles = m.triangleCount();
    for (const auto& j : m.skeleton) info.jointNames.push_back(j.name);
    for (const auto& c : m.animations) info.clipNames.push_back(c.name);
    info.farRoots = a.rootBindings.farRoots;
    info.farDistance = a.rootBindings.farDistance;
    info.meanRootDistance = a.rootBindings.meanDistance;
    info.maxRootDistance = a.rootBindings.maxDistance;
    return info;
  });
}

namespace {
const hp::CharacterMesh& skinnedMesh(const hp::HairAsset& a) {
  if (!a.character || !a.character->skinned())
    throw hp::Error(a.name + " has no skinned character mesh (AssetSource::mesh with a glTF skin or a .tfxmesh)");
  return *a.character;
}
}  // namespace

Result<MeshSkinning> meshSkinning(const Asset& asset) noexcept {
  return guarded<MeshSkinning>("hairpipe::meshSkinning", [&] {
    const hp::HairAsset& a = Access::asset(asset);
    const hp::CharacterMesh& m = skinnedMesh(a);
    MeshSkinning out;
    for (const auto& j : m.skeleton) out.boneNames.push_back(j.name);
    for (const hp::gpu::SkinWeights& s : hp::boundRootSkin(a.rootBindings, m)) {
      SkinWeights w;
      for (int k = 0; k < 4; ++k) w.bones[std::size_t(k)] = s.bones[k], w.weights[std::size_t(k)] = s.weights[k];
      out.skin.push_back(w);
    }
    return out;
  });
}

Result<std::vector<Mat4>> meshClipPose(const Asset& asset, const std::string& clip, float seconds) noexcept {
  return guarded<std::vector<Mat4>>("hairpipe::meshClipPose", [&] {
    const hp::CharacterMesh& m = skinnedMesh(Access::asset(asset));
    if (!std::isfinite(seconds)) throw hp::Error("seconds must be finite");
    std::vector<Mat4> out;
    for (const glm::mat4& s : hp::skinningMatrices(m, hp::samplePose(m, hp::findClip(m, clip), seconds)))
      out.push_back(convert::mat(s));
    return out;
  });
}

Result<Asset> Asset::withDensity(const Density& density) const noexcept {
  return guarded<Asset>("hairpipe::Asset::withDensity", [&] {
    hp::HairAsset copy = Access::asset(*this);
    copy.topology = hp::buildInterpolationTopology(copy.guides.roots(), copy.topology.triangles,
                                                   convert::density(density));
    return Access::makeAsset(std::move(copy));
  });
}

Result<Asset> loadAsset(const AssetSource& source) noexcept {
  return guarded<Asset>("hairpipe::loadAsset", [&] {
    hp::Scene scene;
    scene.source = source.path;
    const std::optional<hp::ModelSpec::Kind> kind = hp::modelKindOf(source.path);
    if (!kind) throw hp::Error("\"" + source.path + "\": expected a path ending in .hair, .tfx or .obj");
    scene.model.kind = *kind;
    scene.model.path = source.path;
    scene.model.transform.scale = source.scale;
    scene.model.transform.up = source.up == UpAxis::Z ? hp::UpAxis::Z : hp::UpAxis::Y;
    scene.model.transform.translation = convert::vec(source.translation);
    scene.model.transform.validate();
    scene.model.keepStrands = source.keepStrands;
    scene.density = convert::density(source.density);
    if (!source.mesh.empty()) {
      if (!hp::meshKindOf(source.mesh))
        throw hp::Error("mesh \"" + source.mesh + "\": expected a path ending in .obj, .ply, .gltf, .glb or .tfxmesh");
      if (!std::isfinite(source.meshCell) || source.meshCell < 0.0f) throw hp::Error("meshCell must be >= 0 (0: automatic)");
      scene.mesh = hp::CharacterMeshSpec{source.mesh, source.meshCell};
    }
    return Access::makeAsset(hp::buildSceneAsset(scene));
  });
}

Result<Asset> defaultHeadAsset(const Density& density) noexcept {
  return guarded<Asset>("hairpipe::defaultHeadAsset", [&] {
    return Access::makeAsset(hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), convert::density(density)));
  });
}

}  // namespace hairpipe
