// hairpipe::Asset, loadAsset and defaultHeadAsset over the core's importers and the default head.
#include <algorithm>
#include <cctype>
#include <filesystem>

#include "engine/api/access.h"
#include "engine/api/convert.h"
#include "engine/hair/default_head.h"
#include "engine/hair/scene.h"
#include "engine/hair/strand_topology.h"

namespace hairpipe {
namespace {
hp::ModelSpec::Kind kindOf(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".hair") return hp::ModelSpec::Kind::Hair;
  if (ext == ".tfx") return hp::ModelSpec::Kind::Tfx;
  if (ext == ".obj") return hp::ModelSpec::Kind::Obj;
  throw hp::Error("\"" + path + "\": expected a path ending in .hair, .tfx or .obj");
}
}  // namespace

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
    scene.model.kind = kindOf(source.path);
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

#define HAIRPIPE_STRINGIFY2(x) #x
#define HAIRPIPE_STRINGIFY(x) HAIRPIPE_STRINGIFY2(x)
const char* versionString() noexcept {
  return HAIRPIPE_STRINGIFY(HAIRPIPE_VERSION_MAJOR) "." HAIRPIPE_STRINGIFY(HAIRPIPE_VERSION_MINOR) "." HAIRPIPE_STRINGIFY(
      HAIRPIPE_VERSION_PATCH);
}
}  // namespace hairpipe
