#pragma once
// Contract: the device side of one Marschner material in one LutMode (docs/THEORY.md §3.7, docs/SHADING.md):
// the lookup textures built on the CPU by buildLut() and uploaded as sampled images (RGBA8 UNORM for
// paper, RGBA16F for float; formats and sizes come from the LutTexture), one linear clamp-to-edge
// sampler, a 1x1 dummy image for the slots a mode does not sample (direct: all three; paper: N1), and
// a storage buffer holding gpu::MarschnerParams (read-only in the shaders). Any pass binds the same resources through
// writeDescriptors(), so the strand fragment shader and the brdf_eval kernel see identical data.
//
// Layout and visibility: after construction and after rebuild() every image is in
// SHADER_READ_ONLY_OPTIMAL (vk::ImageUse::FragmentSampled == ComputeSampled == GraphicsSampled layout),
// and the uploads are made visible to sampled reads in the vertex, fragment and compute stages of any
// later submission on the context's queue; the parameter block is host-coherent memory written before those
// submissions. A frame that only samples them needs no barrier and must not transition them.
//
// Rebuilding happens outside the frame loop and only when the material or the mode changed (rebuild()
// returns false and touches nothing otherwise). It blocks on the context's queue (uploads through
// submitAndWait) and rewrites images and the parameter block in place, so THE CALLER must make sure the GPU no longer
// uses them (e.g. its frame fences, or Context::waitIdle in an owner that owns the queue); hairpipe never
// waits idle on its own. Image views survive a rebuild when every texture's size and format is unchanged;
// a mode change, or a physical material's roughness variation turning on or off (the M texture gains or loses
// its layers), recreates them, so descriptors must be written again after any rebuild() that returned true. An invalid material, or a LUT format the device cannot filter linearly (RGBA32F
// on request), throws hp::Error and leaves the old state; a Vulkan failure during the upload itself
// throws too and leaves the textures unusable.
#include "hairpipe_volk.h"

#include <cstdint>

#include "engine/core/shading/lut.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"
#include "shaders/shared/marschner.h"

namespace hp::vk {
class Context;
class DescriptorSet;
}  // namespace hp::vk

namespace hp::render {
class MarschnerTextures {
 public:
  MarschnerTextures(const vk::Context& ctx, const HairMaterial& material, LutMode mode,
                    const LutBuildOptions& options = {})
      : MarschnerTextures(ctx, buildLut(mode, material, options), options) {}
  // From tables built beforehand (buildLut, e.g. on a worker thread): only the uploads here. `params`:
  // their marschnerGpuParams when computed beforehand too (else computed here: the sky albedo's quadrature).
  MarschnerTextures(const vk::Context& ctx, const MarschnerLut& lut, const LutBuildOptions& options = {},
                    const gpu::MarschnerParams* params = nullptr);
  MarschnerTextures(const MarschnerTextures&) = delete;
  MarschnerTextures& operator=(const MarschnerTextures&) = delete;

  // Rebuilds the LUTs and the parameter block for `material` in `mode` when either differs from the current one;
  // returns whether it did. See the contract above for what the caller must guarantee.
  bool rebuild(const HairMaterial& material, LutMode mode);

  LutMode mode() const { return lut_.mode; }
  const HairMaterial& material() const { return lut_.material; }
  const MarschnerLut& lut() const { return lut_; }  // the CPU tables the images hold
  const gpu::MarschnerParams& params() const { return params_; }
  std::uint32_t buildCount() const { return buildCount_; }  // 1 after construction, +1 per real rebuild

  // Writes the parameter block and the three combined image samplers (M, N0, N1; dummies where the mode
  // has no texture) into `set`. The set's layout must declare paramsBinding as a STORAGE_BUFFER (no shader
  // reads a uniform block: docs/DESIGN.md, driver notes) and the others as COMBINED_IMAGE_SAMPLER.
  void writeDescriptors(const vk::DescriptorSet& set, std::uint32_t paramsBinding, std::uint32_t mBinding,
                        std::uint32_t n0Binding, std::uint32_t n1Binding) const;

  // The image behind slot 0/1/2 (M/N0/N1), for tests and debugging; the dummy where the mode has none.
  const vk::Image& slotImage(std::uint32_t slot) const;

 private:
  void upload(const MarschnerLut& lut, const gpu::MarschnerParams* params = nullptr);

  const vk::Context& ctx_;
  LutBuildOptions options_;
  MarschnerLut lut_;
  gpu::MarschnerParams params_{};
  vk::Image images_[3];
  vk::Image dummy_;
  vk::Buffer paramsBuffer_;
  vk::Sampler sampler_;
  std::uint32_t buildCount_ = 0;
};
}  // namespace hp::render
