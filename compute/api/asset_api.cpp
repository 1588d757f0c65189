// hairpipe::Asset, loadAsset and defaultHeadAsset over the core's importers and the default head.
#include <optional>

#include "compute/api/access.h"
#include "compute/api/convert.h"
#include "engine/core/hair/default_head.h"
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
Result<std::vector<Vec3>> Asset::guideRoots() const noexcept {
  return guarded<std::vector<Vec3>>("hairpipe::Asset::guideRoots", [&] {
    std::vector<Vec3> out;
    for (const glm::vec3& r : Access::asset(*this).guides.roots()) out.push_back({r.x, r.y, r.z});
    return out;
  });
}
const char* Asset::name() const noexcept { return impl_ ? impl_->name.c_str() : ""; }

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
    return Access::makeAsset(hp::buildSceneAsset(scene));
  });
}

Result<Asset> defaultHeadAsset(const Density& density) noexcept {
  return guarded<Asset>("hairpipe::defaultHeadAsset", [&] {
    return Access::makeAsset(hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), convert::density(density)));
  });
}

}  // namespace hairpipe
