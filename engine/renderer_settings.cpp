#include "engine/renderer_settings.h"

#include <cmath>
#include <string>

#include "engine/error.h"

namespace hp {
namespace {
bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
}  // namespace

void RendererSettings::validate() const {
  opacity.validate();
  // The strand shader builds its coverage sample mask in 32 bits (and gl_SampleMask[0] holds 32).
  if (formats.samples > VK_SAMPLE_COUNT_16_BIT) throw Error("RendererSettings.formats.samples must be at most 16");
  if (framesInFlight < 1 || framesInFlight > kMaxFramesInFlight)
    throw Error("RendererSettings.framesInFlight must be in [1, " + std::to_string(kMaxFramesInFlight) + "]");
  if (maxViewsPerFrame < 1 || maxViewsPerFrame > kMaxViewsPerFrame)
    throw Error("RendererSettings.maxViewsPerFrame must be in [1, " + std::to_string(kMaxViewsPerFrame) + "]");
}

void InstanceSettings::validate() const {
  simulation.validate();
  material.validate();
  look.validate();
}

void View::validate(std::uint32_t maxViews) const {
  if (extent.width == 0 || extent.height == 0) throw Error("View.extent must be non-zero");
  if (!finite(camera.view) || !finite(camera.proj) || !std::isfinite(camera.fovY) ||
      !std::isfinite(glm::length(camera.position)))
    throw Error("View.camera must be finite");
  if (index >= maxViews)
    throw Error("View.index " + std::to_string(index) + " is past RendererSettings.maxViewsPerFrame (" +
                std::to_string(maxViews) + ")");
}
}  // namespace hp
