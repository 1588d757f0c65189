#include "compute/raster/marschner_textures.h"

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/shading/half_float.h"
#include "engine/core/shading/lut_cache.h"
#include "engine/core/shading/marschner_gpu.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"

namespace hp::render {
namespace {
constexpr const char* kSlotNames[3] = {"M", "N0", "N1"};

VkFormat vkFormatOf(LutFormat format) {
  switch (format) {
    case LutFormat::RGBA8Unorm: return VK_FORMAT_R8G8B8A8_UNORM;
    case LutFormat::RGBA16F: return VK_FORMAT_R16G16B16A16_SFLOAT;
    case LutFormat::RGBA32F: return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
  throw Error("MarschnerTextures: unknown LUT format");
}

// The LutTexture floats are already quantised to the format, so this conversion is exact.
std::vector<std::byte> texelBytes(const LutTexture& t) {
  const std::size_t n = t.data.size();
  std::vector<std::byte> out;
  switch (t.format) {
    case LutFormat::RGBA8Unorm:
      out.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        float v = std::fmin(std::fmax(t.data[i], 0.0f), 1.0f);
        out[i] = std::byte(static_cast<std::uint8_t>(std::lround(v * 255.0f)));
      }
      break;
    case LutFormat::RGBA16F:
      out.resize(n * 2);
      for (std::size_t i = 0; i < n; ++i) {
        std::uint16_t h = shading::floatToHalf(t.data[i]);
        std::memcpy(&out[i * 2], &h, 2);
      }
      break;
    case LutFormat::RGBA32F:
      out.resize(n * 4);
      std::memcpy(out.data(), t.data.data(), n * 4);
      break;
  }
  return out;
}

void requireLinearFiltering(const vk::Context& ctx, VkFormat format, const std::string& name) {
  VkFormatProperties props{};
  vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), format, &props);
  const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  if ((props.optimalTilingFeatures & need) != need)
    throw Error("Marschner LUT '" + name + "': format " + std::to_string(format) +
                " cannot be sampled with linear filtering on " + ctx.properties().deviceName);
}

// Uploads end in GraphicsSampled (vertex + fragment); one more read-to-read barrier extends the
// dependency to compute sampling, so every later consumer is covered without its own barrier.
void makeVisibleToComputeToo(const vk::Context& ctx, const std::vector<const vk::Image*>& images) {
  if (images.empty()) return;
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    for (const vk::Image* image : images)
      vk::imageBarrier(ctx, cmd, image->handle(), image->aspect(), vk::ImageUse::GraphicsSampled,
                       vk::ImageUse::ComputeSampled);
  }, "Marschner LUT visibility");
}
}  // namespace

MarschnerTextures::MarschnerTextures(const vk::Context& ctx, const MarschnerLut& lut, const LutBuildOptions& options,
                                     const gpu::MarschnerParams* params)
    : ctx_(ctx), options_(options) {
  sampler_ = vk::Sampler(ctx, "Marschner LUT sampler");
  vk::ImageDesc dummy;
  dummy.format = VK_FORMAT_R8G8B8A8_UNORM;
  dummy.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  dummy.name = "Marschner LUT dummy 1x1";
  dummy_ = vk::Image(ctx, dummy);
  const std::byte zero[4] = {};
  vk::uploadImage(ctx, dummy_, zero, vk::ImageUse::GraphicsSampled);
  makeVisibleToComputeToo(ctx, {&dummy_});
  paramsBuffer_ = vk::Buffer(ctx, sizeof(gpu::MarschnerParams),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             vk::MemoryKind::Upload, "Marschner params");
  upload(lut, params);
}

bool MarschnerTextures::rebuild(const HairMaterial& material, LutMode mode) {
  if (mode == lut_.mode && material == lut_.material) return false;
  upload(*sharedLut(mode, material, options_));
  return true;
}

void MarschnerTextures::upload(const MarschnerLut& lut, const gpu::MarschnerParams* params) {
  // Refuse an unusable format before touching anything, so that failure keeps the old state too.
  for (const LutTexture& t : lut.textures) requireLinearFiltering(ctx_, vkFormatOf(t.format), t.name);
  std::vector<const vk::Image*> uploaded;
  for (std::uint32_t slot = 0; slot < 3; ++slot) {
    if (slot >= lut.textures.size()) {
      images_[slot] = vk::Image();  // this mode samples the dummy here
      continue;
    }
    const LutTexture& t = lut.textures[slot];
    const VkFormat format = vkFormatOf(t.format);
    const vk::ImageDesc& have = images_[slot].desc();
    // Same size and format (same mode): refill in place so existing descriptors stay valid.
    if (!images_[slot] || have.width != t.width || have.height != t.height || have.format != format) {
      vk::ImageDesc desc;
      desc.width = t.width;
      desc.height = t.height;
      desc.format = format;
      desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
      desc.name = std::string("Marschner LUT ") + lutModeName(lut.mode) + " " + kSlotNames[slot] + " (" + t.name + ")";
      images_[slot] = vk::Image(ctx_, desc);
    }
    vk::uploadImage(ctx_, images_[slot], texelBytes(t), vk::ImageUse::GraphicsSampled);
    uploaded.push_back(&images_[slot]);
  }
  makeVisibleToComputeToo(ctx_, uploaded);
  params_ = params ? *params : marschnerGpuParams(lut);
  std::memcpy(paramsBuffer_.mapped(), &params_, sizeof(params_));  // coherent; visible to later submits
  lut_ = lut;
  ++buildCount_;
}

const vk::Image& MarschnerTextures::slotImage(std::uint32_t slot) const {
  if (slot > 2) throw Error("MarschnerTextures::slotImage: slot " + std::to_string(slot) + " is not 0, 1 or 2");
  return images_[slot] ? images_[slot] : dummy_;
}

void MarschnerTextures::writeDescriptors(const vk::DescriptorSet& set, std::uint32_t paramsBinding,
                                         std::uint32_t mBinding, std::uint32_t n0Binding,
                                         std::uint32_t n1Binding) const {
  set.writeStorageBuffer(paramsBinding, paramsBuffer_.handle());
  const std::uint32_t bindings[3] = {mBinding, n0Binding, n1Binding};
  for (std::uint32_t slot = 0; slot < 3; ++slot)
    set.writeSampledImage(bindings[slot], slotImage(slot).view(), sampler_.handle(),
                          vk::imageLayout(vk::ImageUse::FragmentSampled));
}
}  // namespace hp::render
