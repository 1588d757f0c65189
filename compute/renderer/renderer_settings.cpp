#include "compute/renderer/renderer_settings.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/hair/finite.h"
#include "engine/vk/application_attachments.h"
#include "engine/vk/image.h"

namespace hp {
RasterMode resolveRasterMode(RasterMode mode, VkPhysicalDeviceType type) {
  if (mode != RasterMode::Auto) return mode;
  // Measured on lavapipe (CPU): compute 10x cheaper than MSAA 4 ribbons (docs/PERFORMANCE.md). GPUs are
  // unmeasured here; compute is the default there too, on the fragment-vs-compute evidence.
  (void)type;
  return RasterMode::Compute;
}

void RendererSettings::validate() const {
  render::validate(opacity);
  rasterSettings.validate();
  vk::validateAttachmentFormats(formats);  // samples at most 16: the strand shader's coverage mask is 32 bits
  if (framesInFlight < 1 || framesInFlight > kMaxFramesInFlight)
    throw Error("RendererSettings.framesInFlight must be in [1, " + std::to_string(kMaxFramesInFlight) + "]");
  if (maxViewsPerFrame < 1 || maxViewsPerFrame > kMaxViewsPerFrame)
    throw Error("RendererSettings.maxViewsPerFrame must be in [1, " + std::to_string(kMaxViewsPerFrame) + "]");
  if (shadowedLights < 1 || shadowedLights > gpu::OPACITY_MAX_LIGHTS)
    throw Error("RendererSettings.shadowedLights must be in [1, " + std::to_string(gpu::OPACITY_MAX_LIGHTS) + "], got " +
                std::to_string(shadowedLights));
  validateVelocityOutput(velocityOutput, formats, motionVectors);
}

void validateVelocityOutput(const hairpipe::VelocityOutput& v, const hairpipe::AttachmentFormats& formats,
                            bool motionVectors) {
  const std::string field = "RendererSettings.velocityOutput.";
  const int others = int(formats.otherColors.size());
  if (v.attachment < -1 || v.attachment >= others)
    throw Error(field + "attachment must be -1 (none) or an index into formats.otherColors (" + std::to_string(others) +
                " of them), got " + std::to_string(v.attachment));
  if (v.attachment < 0) return;
  if (!motionVectors) throw Error(field + "attachment needs RendererSettings.motionVectors: the motion it writes");
  const VkFormat format = formats.otherColors[std::size_t(v.attachment)];
  const std::string target = field + "attachment: formats.otherColors[" + std::to_string(v.attachment) + "] is ";
  const std::string named = " (VkFormat " + std::to_string(int(format)) + ")";
  if (format == VK_FORMAT_UNDEFINED) throw Error(target + "an unused slot (VK_FORMAT_UNDEFINED)");
  if (vk::isSrgbFormat(format)) throw Error(target + "an SRGB format" + named + "; the motion would be gamma-encoded");
  if (vk::isIntegerColorFormat(format))
    throw Error(target + "an integer format" + named + "; the motion is written as floats");
  for (const auto& [value, name] : {std::pair{v.scaleX, "scaleX"}, {v.scaleY, "scaleY"}, {v.offsetX, "offsetX"},
                                    {v.offsetY, "offsetY"}})
    if (!std::isfinite(value)) throw Error(field + name + " must be finite, got " + numberText(value));
  if (!(v.minCoverage >= 0.0f && v.minCoverage < 1.0f))  // the coverage is at most 1: 1 would write nothing
    throw Error(field + "minCoverage must be in [0, 1), got " + numberText(v.minCoverage));
}

void InstanceSettings::validate() const {
  simulation.validate();
  material.validate();
  look.validate();
  hp::validate(lod);
  groom.validate();
  compute::validateBounceSamples(strands.bounceSamples, "InstanceSettings: skinBounceSamples");
}

void validate(const hairpipe::LodSettings& lod) {
  if (!std::isfinite(lod.startDistance) || !std::isfinite(lod.endDistance) || lod.startDistance < 0.0f ||
      !(lod.endDistance > lod.startDistance))
    throw Error("LodSettings: the distances must be finite with 0 <= startDistance < endDistance, got " +
                std::to_string(lod.startDistance) + " and " + std::to_string(lod.endDistance));
  // (A fraction that rounds to 0 in lodFraction's blend would be a division by it.)
  if (!(lod.minFraction >= kMinLodFraction && lod.minFraction <= 1.0f))
    throw Error("LodSettings.minFraction must be in [" + numberText(kMinLodFraction) + ", 1], got " +
                numberText(lod.minFraction));
}

float lodFraction(const hairpipe::LodSettings& lod, float distance) {
  if (!lod.enabled || !(distance > lod.startDistance)) return 1.0f;
  const float t = std::min(1.0f, (distance - lod.startDistance) / (lod.endDistance - lod.startDistance));
  return 1.0f + t * (lod.minFraction - 1.0f);
}

render::LookSettings lodLook(render::LookSettings look, float fraction) {
  look.strandWidth /= fraction;
  return look;
}

ShadowSample shadowSample(float lodFraction, std::uint32_t strands, std::uint32_t budget) {
  ShadowSample s{lodStrandCount(lodFraction, strands), lodFraction};
  if (budget != 0 && s.drawn > budget) {
    s.drawn = budget;
    s.fraction = float(double(budget) / double(strands));
  }
  return s;
}

std::uint32_t lodStrandCount(float fraction, std::uint32_t strands) {
  const double n = std::ceil(double(fraction) * double(strands));
  return std::uint32_t(std::clamp(n, 1.0, double(strands)));
}

void View::validate(std::uint32_t maxViews, bool reversedDepth) const {
  if (extent.width == 0 || extent.height == 0) throw Error("View.extent must be non-zero");
  if (!allFinite(camera.view) || !allFinite(camera.proj) || !std::isfinite(camera.fovY) ||
      !std::isfinite(glm::length(camera.position)))
    throw Error("the view's matrices, eye and fovY must be finite");
  // The strands' width in pixels follows from fovY: a value no projection has would draw them wrongly sized.
  if (!(camera.fovY > 0.0f && camera.fovY < 3.14159f))
    throw Error("View.fovY must be in (0, pi) radians, got " + numberText(camera.fovY));
  if (!(std::abs(jitter.x) <= 1.0f && std::abs(jitter.y) <= 1.0f))
    throw Error("View.jitter must be finite, within [-1, 1] pixels, got (" + numberText(jitter.x) + ", " +
                numberText(jitter.y) + ")");
  if (previousViewProj && !allFinite(*previousViewProj)) throw Error("View.previousViewProj must be finite");
  if (index >= maxViews)
    throw Error("View.index " + std::to_string(index) + " is past RendererSettings.maxViewsPerFrame (" +
                std::to_string(maxViews) + ")");
  if (!fromApplication) return;
  const float slope = camera.proj[2][2];
  if (reversedDepth ? slope < 0.0f : slope >= 0.0f)
    throw Error(std::string("View.projection maps depth ") + (reversedDepth ? "forward" : "reversed (near to 1)") +
                ", but RendererSettings.formats.reversedDepth is " + (reversedDepth ? "true" : "false"));
}
}  // namespace hp
