#pragma once
// Contract: the opacity maps and the light framing of the last recorded frame, copied to the host
// (blocking readback, outside the frame loop: tools, tests, `hairpipe render --dump-opacity`), and
// their files: one PFM per slice, a PNG contact sheet and a JSON of the slice depths, each written
// atomically. Expects the maps in ImageUse::FragmentSampled and LightSpace in BufferUse::VertexRead,
// where HairSystem leaves them after a frame.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "compute/shadows/opacity_settings.h"
#include "shaders/shared/opacity.h"

namespace hp::vk {
class Context;
class Image;
class Buffer;
}  // namespace hp::vk

namespace hp::render {
struct OpacityCapture {
  std::uint32_t resolution = 0;
  std::vector<float> alpha;  // alpha(z_i): slice-major (i = 1..16 -> index 0..15), rows top to bottom
                             // (row 0 is light-space +y, clip y = +1), resolution^2 per slice
  std::vector<float> firstHair;  // per texel, rows top to bottom: deep maps (settings.deep) only, the first
                                 // hair's global slice coordinate s0 (OPACITY_NO_HAIR where none)
  gpu::LightSpace light{};
  OpacitySettings settings;
  glm::vec3 towardLight{0.0f, 0.0f, 1.0f};

  float at(std::uint32_t slice, std::uint32_t x, std::uint32_t y) const {
    return alpha[(std::size_t(slice) * resolution + y) * resolution + x];
  }
  float sliceDepth(std::uint32_t i) const { return light.depthRange.x + float(i) * light.depthRange.z; }  // z_i
};

OpacityCapture captureOpacity(const vk::Context& ctx, const vk::Image& maps, const vk::Buffer& lightSpace,
                              const OpacitySettings& settings, const glm::vec3& towardLight);

// Writes DIR/opacity_slice_01.pfm .. _16.pfm (alpha, 1 channel, viewed with light +y up),
// DIR/opacity_contact_sheet.png (transmittance exp(-k alpha) of the 16 slices, 4 x 4, slice 1 top
// left) and DIR/opacity_slices.json (z_near, z_far, d_z, the 16 z_i and the framing).
void writeOpacityDump(const std::filesystem::path& dir, const OpacityCapture& capture);
}  // namespace hp::render
