#pragma once
// Contract: the opacity shadow maps of up to OPACITY_MAX_LIGHTS shadowed lights (`slots`), shared by every
// hair instance a Renderer draws, so heads shadow each other (docs/THEORY.md §5; compute/shadows/README.md
// "Opacity shadow maps"). Owns the buffer of one LightSpace per slot that the bounds pass of every instance
// reduces into (one framing per light over all of them), the 2D-array image of OPACITY_LAYERS layers per
// slot (4 RGBA layers = 16 slices, and the deep maps' first-hair layer) every instance's OpacityPass draws
// into, and its sampler. beginRendering(slot)/endRendering() open and close the additive rendering into a
// slot's 4 layers (cleared to 0); the instances' OpacityPass::recordDraws go between them. Inserts no
// barriers: the frame recorder (hp::recordShadowPasses) owns them.
// Also owns the heads' depth shadow map (D32, back faces, head_shadow.glsl; a layer per slot) every
// instance's head is drawn into, with its compare sampler: the head occludes hair and itself through it,
// not the slices; and the head bounce map (HeadBounceMap, the skin seen from slot 0's light) the hair
// gathers the skin's light from.
// On the compute path (OpacityRaster::Compute, or Auto where the bins fit the device) it also owns the bins
// and resolve pass (compute::OpacityResolvePass) and the image has storage usage.
// Construction clears the image (alpha = 0, T = 1) and the head map (far plane: lit) and leaves them in
// ImageUse::FragmentSampled, and
// uploads an armed LightSpace (compute::initialLightSpace) left in BufferUse::GraphicsRead, so a frame with
// shadows off samples valid data. One blocking submission. Throws hp::Error on invalid settings.
#include <memory>

#include "compute/shadows/opacity_resolve_pass.h"
#include "compute/shadows/head_bounce_map.h"
#include "compute/shadows/opacity_settings.h"
#include "compute/shadows/shadow_inputs.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"

namespace hp::render {
class ShadowMaps {
 public:
  static constexpr VkFormat kHeadDepthFormat = VK_FORMAT_D32_SFLOAT;

  // How compute deep maps splat: Auto, in one splat into fine bins where they fit the device
  // (compute::OpacityResolvePass::binsFor); Two, the first hair and then the slices (tests compare the two).
  enum class DeepSplats { Auto, Two };

  // `library`: the Renderer's, through which the opacity resolve's pipeline is built (null: its own).
  // slots: [1, OPACITY_MAX_LIGHTS].
  ShadowMaps(const vk::Context& ctx, const OpacitySettings& settings, vk::PipelineLibrary* library = nullptr,
             std::uint32_t slots = 1, DeepSplats deepSplats = DeepSplats::Auto);
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // New opacities, k, bias or on/off with the same resolution and format (read at record time).
  void setTuning(const OpacitySettings& settings) {
    const bool deep = settings_.deep;  // as in effect (not as asked for)
    settings_ = settings;
    settings_.deep = deep;
  }

  // A slot's 4 slice layers; keep: load them (the compute resolve wrote them) instead of clearing them to 0.
  void beginRendering(VkCommandBuffer cmd, std::uint32_t slot, bool keep = false) const;
  void endRendering(VkCommandBuffer cmd) const;
  // A slot's layer of the heads' depth map (back faces, cleared to the far plane): OpacityPass::recordHeadDepth
  // between.
  void beginHeadRendering(VkCommandBuffer cmd, std::uint32_t slot) const;
  std::uint32_t slots() const { return slots_; }

  const vk::Image& image() const { return image_; }
  const vk::Image& headImage() const { return headImage_; }
  const vk::Buffer& lightSpace() const { return lightSpace_; }
  const HeadBounceMap& bounceMap() const { return bounce_; }
  // The compute path: the bins the instances' splats add into and their resolve; null otherwise.
  const compute::OpacityResolvePass* resolvePass() const { return resolve_.get(); }
  ShadowInputs inputs() const {
    return {image_.view(),          sampler_.handle(),        lightSpace_.handle(),
            headImage_.view(),      headSampler_.handle(),    bounce_.fluxView(),
            bounce_.positionView(), bounce_.sampler()};
  }
  // The settings in effect: as given, but `deep` only where the compute path was taken.
  const OpacitySettings& settings() const { return settings_; }
  // The path taken: settings().raster, with Auto resolved for this device and resolution.
  OpacityRaster raster() const { return resolve_ ? OpacityRaster::Compute : OpacityRaster::Graphics; }

 private:
  const vk::Context* ctx_;
  OpacitySettings settings_;
  std::uint32_t slots_;
  vk::Buffer lightSpace_;
  vk::Image image_;
  vk::Sampler sampler_;
  vk::Image headImage_;    // D32, settings.headShadowResolution^2
  vk::Sampler headSampler_;  // depth compare
  HeadBounceMap bounce_;
  std::unique_ptr<compute::OpacityResolvePass> resolve_;
};
}  // namespace hp::render
