// The helpers of hairpipe/settings.h and hairpipe/renderer.h that compute values: absorptionFromColor, makeView,
// loadTfxBoneSkinning, environmentLighting, studioEnvironment.
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "compute/api/access.h"
#include "compute/api/convert.h"
#include "compute/raster/frame_block.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "engine/core/shading/environment_lights.h"
#include "engine/core/shading/material_color.h"
#include "engine/core/number_text.h"

namespace hairpipe {
Result<std::array<double, 3>> absorptionFromColor(float r, float g, float b) noexcept {
  return guarded<std::array<double, 3>>("hairpipe::absorptionFromColor", [&] {
    const glm::dvec3 a = hp::absorptionFromColor({r, g, b});
    return std::array<double, 3>{a.x, a.y, a.z};
  });
}

Result<TfxBoneSkinning> loadTfxBoneSkinning(const std::string& path, std::uint32_t guideCount) noexcept {
  return guarded<TfxBoneSkinning>("hairpipe::loadTfxBoneSkinning", [&] {
    const hp::TfxBoneData data = hp::readTfxBoneFile(path);
    TfxBoneSkinning out;
    out.boneNames = data.boneNames;
    for (const hp::gpu::SkinWeights& s : hp::tfxBoneSkinWeights(data, guideCount, path)) {
      SkinWeights w;
      for (int k = 0; k < 4; ++k) {
        w.bones[k] = s.bones[k];
        w.weights[k] = s.weights[k];
      }
      out.skin.push_back(w);
    }
    return out;
  });
}

Result<EnvironmentLighting> environmentLighting(const EnvironmentImage& image, std::uint32_t maxLights) noexcept {
  return guarded<EnvironmentLighting>("hairpipe::environmentLighting", [&] {
    hp::EnvironmentMap map{image.width, image.height, {}, image.rotationDeg, image.intensity};
    map.texels.reserve(image.texels.size());
    for (const Vec3& t : image.texels) map.texels.push_back(convert::vec(t));
    const hp::EnvironmentSplit split = hp::splitEnvironment(map, {maxLights});
    EnvironmentLighting out;
    for (const hp::EnvironmentLight& e : split.lights) {
      Light l;
      l.direction = convert::vec(glm::vec3(e.direction));
      l.color = convert::vec(glm::vec3(e.color()));
      l.intensity = float(e.intensity());
      out.lights.push_back(l);
    }
    for (std::size_t i = 0; i < split.residual.size(); ++i) out.harmonics[i] = convert::vec(glm::vec3(split.residual[i]));
    hp::render::LookSettings look;  // the harmonics must pass the look they are for
    for (std::size_t i = 0; i < split.residual.size(); ++i) look.environment[i] = glm::vec3(split.residual[i]);
    look.validate();
    return out;
  });
}

Result<EnvironmentImage> studioEnvironment() noexcept {
  return guarded<EnvironmentImage>("hairpipe::studioEnvironment", [] {
    const hp::EnvironmentMap map = hp::studioEnvironment();
    EnvironmentImage out{map.width, map.height, {}, 0.0, 1.0};
    for (const glm::vec3& t : map.texels) out.texels.push_back(convert::vec(t));
    return out;
  });
}

Result<View> makeView(const Camera& c, VkExtent2D extent, std::uint32_t index) noexcept {
  return guarded<View>("hairpipe::makeView", [&]() -> View {
    const glm::vec3 eye = convert::vec(c.eye), target = convert::vec(c.target), up = convert::vec(c.up);
    const glm::vec3 forward = target - eye;
    const float side = glm::length(glm::cross(forward, up));
    if (!std::isfinite(side) || glm::length(forward) <= 0.0f || side <= 1e-6f * glm::length(forward) * glm::length(up))
      throw hp::Error("the eye is at the target, or up is parallel to the view direction (or not finite)");
    if (!(c.fovY > 0.0f && c.fovY < 3.14159f)) throw hp::Error("fovY must be in (0, pi) radians, got " + hp::numberText(c.fovY));
    if (!(c.nearZ > 0.0f && c.farZ > c.nearZ && std::isfinite(c.farZ)))
      throw hp::Error("the clip planes need 0 < nearZ < farZ, got " + hp::numberText(c.nearZ) + ", " + hp::numberText(c.farZ));
    if (extent.width == 0 || extent.height == 0) throw hp::Error("the extent must not be empty");
    View v;
    v.view = convert::mat(glm::lookAtRH(eye, target, up));
    // Reversed-Z: the same projection with the planes swapped maps near to 1 and far to 0.
    const float aspect = float(extent.width) / float(extent.height);
    v.projection = convert::mat(c.reversedDepth ? glm::perspectiveRH_ZO(c.fovY, aspect, c.farZ, c.nearZ)
                                                : glm::perspectiveRH_ZO(c.fovY, aspect, c.nearZ, c.farZ));
    v.eye = c.eye;
    v.fovY = c.fovY;
    v.extent = extent;
    v.index = index;
    return v;
  });
}
}  // namespace hairpipe
