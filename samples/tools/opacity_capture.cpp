#include "samples/tools/opacity_capture.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "samples/tools/png_file.h"
#include "engine/core/shading/half_float.h"
#include "samples/tools/host/lut_export.h"
#include "engine/vk/transfer.h"
#include "samples/tools/host/json_text.h"

namespace hp::render {
namespace {
constexpr std::uint32_t kSheetTile = 256;  // contact sheet tiles are at most this many texels wide

std::vector<float> texelsAsFloat(const std::vector<std::byte>& bytes, VkFormat format) {
  std::vector<float> out;
  if (format == VK_FORMAT_R32G32B32A32_SFLOAT) {
    out.resize(bytes.size() / 4);
    std::memcpy(out.data(), bytes.data(), bytes.size());
    return out;
  }
  out.resize(bytes.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::uint16_t h;
    std::memcpy(&h, &bytes[i * 2], 2);
    out[i] = shading::halfToFloat(h);
  }
  return out;
}

std::string sliceName(std::uint32_t i) {
  return std::string("opacity_slice_") + (i < 10 ? "0" : "") + std::to_string(i) + ".pfm";
}

std::vector<std::byte> sliceOfPfm(const OpacityCapture& c, std::uint32_t slice) {
  // PFM rows go bottom to top: reverse, so a viewer shows light +y up.
  const std::uint32_t n = c.resolution;
  std::vector<float> rows(std::size_t(n) * n);
  for (std::uint32_t y = 0; y < n; ++y)
    for (std::uint32_t x = 0; x < n; ++x) rows[std::size_t(n - 1 - y) * n + x] = c.at(slice, x, y);
  return encodePfm(n, n, 1, rows.data());
}

std::vector<std::uint8_t> contactSheet(const OpacityCapture& c, std::uint32_t& side) {
  const std::uint32_t tile = std::min(c.resolution, kSheetTile);
  const std::uint32_t step = (c.resolution + tile - 1) / tile;
  side = 4 * tile;
  std::vector<std::uint8_t> rgb(std::size_t(side) * side * 3, 0);
  for (std::uint32_t s = 0; s < gpu::OPACITY_SLICES; ++s)
    for (std::uint32_t ty = 0; ty < tile; ++ty)
      for (std::uint32_t tx = 0; tx < tile; ++tx) {
        const std::uint32_t x = std::min(tx * step, c.resolution - 1), y = std::min(ty * step, c.resolution - 1);
        const float t = std::exp(-c.settings.k * c.at(s, x, y));
        const auto v = static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(t, 0.0f, 1.0f)));
        const std::size_t px = (std::size_t((s / 4) * tile + ty) * side + (s % 4) * tile + tx) * 3;
        rgb[px] = rgb[px + 1] = rgb[px + 2] = v;
      }
  return rgb;
}

nlohmann::json sliceJson(const OpacityCapture& c) {
  const gpu::LightSpace& l = c.light;
  nlohmann::json depths = nlohmann::json::array(), maxAlpha = nlohmann::json::array();
  for (std::uint32_t i = 1; i <= gpu::OPACITY_SLICES; ++i) {
    depths.push_back(c.sliceDepth(i));
    const auto begin = c.alpha.begin() + std::ptrdiff_t(i - 1) * c.resolution * c.resolution;
    maxAlpha.push_back(*std::max_element(begin, begin + std::ptrdiff_t(c.resolution) * c.resolution));
  }
  nlohmann::json viewProj = nlohmann::json::array();
  for (int row = 0; row < 4; ++row)
    viewProj.push_back({l.viewProj[0][row], l.viewProj[1][row], l.viewProj[2][row], l.viewProj[3][row]});
  return {{"resolution", c.resolution},
          {"slices", gpu::OPACITY_SLICES},
          {"depth_convention", c.settings.deep
                                   ? "deep: slice i of a texel at light depth s0 + i d_z / OPACITY_DEEP_FACTOR "
                                     "(s0 its first hair, in slices of d_z from z_near); the last "
                                     "slice reaches to infinity"
                                   : "light depth d = -dot(L, p), growing away from the light; z_i = z_near + i d_z"},
          {"deep", c.settings.deep},
          {"deep_factor", gpu::OPACITY_DEEP_FACTOR},
          {"z_near", l.depthRange.x},
          {"z_far", l.depthRange.y},
          {"d_z", l.depthRange.z},
          {"slice_depths", depths},
          {"max_alpha", maxAlpha},
          {"light_direction", {c.towardLight.x, c.towardLight.y, c.towardLight.z}},
          {"light_extent", {{"x_min", l.extent.x}, {"y_min", l.extent.y}, {"x_max", l.extent.z}, {"y_max", l.extent.w}}},
          {"view_proj_rows", viewProj},
          {"k", c.settings.k},
          {"strand_opacity", c.settings.strandOpacity},
          {"strand_opacity_mode", c.settings.footprint ? "footprint" : "constant"},
          {"head_opacity", c.settings.headOpacity},
          {"bias_slices", c.settings.biasSlices},
          {"deep_bias_slices", c.settings.deepBiasSlices}};
}

std::vector<std::byte> bytesOf(const std::string& s) {
  std::vector<std::byte> out(s.size());
  std::memcpy(out.data(), s.data(), s.size());
  return out;
}
}  // namespace

OpacityCapture captureOpacity(const vk::Context& ctx, const vk::Image& maps, const vk::Buffer& lightSpace,
                              const OpacitySettings& settings, const glm::vec3& towardLight) {
  OpacityCapture c;
  c.resolution = maps.desc().width;
  c.settings = settings;
  c.towardLight = towardLight;
  const std::size_t perSlice = std::size_t(c.resolution) * c.resolution;
  c.alpha.resize(perSlice * gpu::OPACITY_SLICES);
  for (std::uint32_t layer = 0; layer < gpu::OPACITY_TARGETS; ++layer) {
    const std::vector<float> rgba =
        texelsAsFloat(vk::readbackImage(ctx, maps, vk::ImageUse::FragmentSampled, layer), maps.desc().format);
    for (std::uint32_t ch = 0; ch < 4; ++ch)
      for (std::size_t t = 0; t < perSlice; ++t) c.alpha[(layer * 4 + ch) * perSlice + t] = rgba[t * 4 + ch];
  }
  const std::vector<float> first =
      texelsAsFloat(vk::readbackImage(ctx, maps, vk::ImageUse::FragmentSampled, gpu::OPACITY_TARGETS), maps.desc().format);
  c.firstHair.resize(perSlice);
  for (std::size_t t = 0; t < perSlice; ++t) c.firstHair[t] = first[t * 4];
  c.light = vk::readback<gpu::LightSpace>(ctx, lightSpace, vk::BufferUse::GraphicsRead, 1).front();
  return c;
}

void writeOpacityDump(const std::filesystem::path& dir, const OpacityCapture& c) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create " + dir.string() + ": " + ec.message());
  removeBeforeRewrite(dir / "opacity_slices.json");  // the JSON describing the slices goes first, comes back last
  for (std::uint32_t s = 0; s < gpu::OPACITY_SLICES; ++s) writeFileAtomically(dir / sliceName(s + 1), sliceOfPfm(c, s));
  std::uint32_t side = 0;
  const std::vector<std::uint8_t> sheet = contactSheet(c, side);
  writePng(dir / "opacity_contact_sheet.png", side, side, 3, sheet);
  writeFileAtomically(dir / "opacity_slices.json", bytesOf(hp::jsonText(sliceJson(c)) + "\n"));
}
}  // namespace hp::render
