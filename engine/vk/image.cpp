#include "engine/vk/image.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
bool hasStencilComponent(VkFormat format) {
  return format == VK_FORMAT_D16_UNORM_S8_UINT || format == VK_FORMAT_D24_UNORM_S8_UINT ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

bool isDepthFormat(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM || hasStencilComponent(format);
}

bool isIntegerColorFormat(VkFormat format) {
  // The core UINT / SINT colour formats come in adjacent pairs (vulkan_core.h), from R8 to R64G64B64A64.
  constexpr int kFirstOfPairs[] = {13, 20, 27, 34, 41, 48, 55, 62, 68, 74, 81, 88, 95, 98, 101, 104, 107, 110, 113, 116, 119};
  static_assert(VK_FORMAT_R8_UINT == 13 && VK_FORMAT_R64G64B64A64_SINT == 120);
  const int f = int(format);
  for (const int first : kFirstOfPairs)
    if (f == first || f == first + 1) return true;
  return false;
}

bool isSrgbFormat(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_SRGB:
    case VK_FORMAT_R8G8_SRGB:
    case VK_FORMAT_R8G8B8_SRGB:
    case VK_FORMAT_B8G8R8_SRGB:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A8B8G8R8_SRGB_PACK32:
      return true;
    default:
      return false;
  }
}

std::uint32_t formatBytesPerPixel(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT:
      return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: throw Error("formatBytesPerPixel: unsupported format " + std::to_string(format));
  }
}

VkImageAspectFlags Image::aspect() const {
  return isDepthFormat(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

Image::Image(const Context& ctx, const ImageDesc& desc) : device_(ctx.device()), fn_(&ctx.fn()), desc_(desc) {
  const auto& limits = ctx.properties().limits;
  if (desc.width == 0 || desc.height == 0 || desc.width > limits.maxImageDimension2D ||
      desc.height > limits.maxImageDimension2D)
    throw Error("image '" + desc.name + "': size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                " is outside 1.." + std::to_string(limits.maxImageDimension2D) + " for this device");
  if (desc.layers == 0 || desc.layers > limits.maxImageArrayLayers)
    throw Error("image '" + desc.name + "': bad layer count " + std::to_string(desc.layers));
  if (desc.groupLayers > 0 && desc.layers % desc.groupLayers != 0)
    throw Error("image '" + desc.name + "': " + std::to_string(desc.layers) + " layers are not whole groups of " +
                std::to_string(desc.groupLayers));
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = desc.layers;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  HP_VK_CHECK(fn_->vkCreateImage(device_, &info, nullptr, &image_));
  try {
    ctx.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(image_), desc.name);
    const MemoryRequest request = ctx.memoryPool().imageRequest(image_);
    ctx.checkDeviceMemoryBudget(request.requirements.size, "image '" + desc.name + "'");
    pool_ = &ctx.memoryPool();
    memory_ = pool_->allocate(request);
    tally_ = ctx.allocationTally();
    allocated_ = request.requirements.size;
    *tally_ += std::int64_t(allocated_);
    HP_VK_CHECK(fn_->vkBindImageMemory(device_, image_, memory_.memory, memory_.offset));
    const bool array = desc.layers > 1 || desc.arrayView;
    view_ = createView(ctx, array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D, 0, desc.layers,
                       desc.name + " view");
    if (array)
      for (std::uint32_t i = 0; i < desc.layers; ++i)
        layerViews_.push_back(createView(ctx, VK_IMAGE_VIEW_TYPE_2D, i, 1, desc.name + " layer " + std::to_string(i)));
    else
      layerViews_.push_back(view_);
    if (desc.groupLayers > 0)
      for (std::uint32_t g = 0; g < desc.layers / desc.groupLayers; ++g)
        groupViews_.push_back(createView(ctx, VK_IMAGE_VIEW_TYPE_2D_ARRAY, g * desc.groupLayers, desc.groupLayers,
                                         desc.name + " group " + std::to_string(g)));
  } catch (...) {
    release();
    throw;
  }
}

VkImageView Image::createView(const Context& ctx, VkImageViewType type, std::uint32_t firstLayer,
                              std::uint32_t layerCount, const std::string& name) {
  VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  info.image = image_;
  info.viewType = type;
  info.format = desc_.format;
  info.subresourceRange = {aspect(), 0, 1, firstLayer, layerCount};
  VkImageView view = VK_NULL_HANDLE;
  HP_VK_CHECK(fn_->vkCreateImageView(device_, &info, nullptr, &view));
  ctx.setName(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<std::uint64_t>(view), name);
  return view;
}

Image::~Image() { release(); }

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, nullptr);
    memory_ = std::exchange(other.memory_, MemoryAllocation{});
    tally_ = std::move(other.tally_);
    allocated_ = std::exchange(other.allocated_, 0);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    layerViews_ = std::move(other.layerViews_);
    other.layerViews_.clear();
    groupViews_ = std::move(other.groupViews_);
    other.groupViews_.clear();
    desc_ = std::move(other.desc_);
  }
  return *this;
}

void Image::release() {
  if (!device_) return;
  for (VkImageView v : layerViews_)
    if (v != view_) fn_->vkDestroyImageView(device_, v, nullptr);
  layerViews_.clear();
  for (VkImageView v : groupViews_) fn_->vkDestroyImageView(device_, v, nullptr);
  groupViews_.clear();
  if (view_) fn_->vkDestroyImageView(device_, view_, nullptr);
  if (image_) fn_->vkDestroyImage(device_, image_, nullptr);
  if (pool_) pool_->free(memory_);
  if (tally_) *tally_ -= std::int64_t(allocated_);
  tally_.reset();
  allocated_ = 0;
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  pool_ = nullptr;
  memory_ = {};
}

Sampler::Sampler(const Context& ctx, const std::string& name, VkFilter filter)
    : Sampler(ctx, name, filter, VK_COMPARE_OP_MAX_ENUM) {}

Sampler::Sampler(const Context& ctx, const std::string& name, VkCompareOp compare)
    : Sampler(ctx, name, VK_FILTER_LINEAR, compare) {}

Sampler::Sampler(const Context& ctx, const std::string& name, VkFilter filter, VkCompareOp compare)
    : device_(ctx.device()), fn_(&ctx.fn()) {
  const bool depthCompare = compare != VK_COMPARE_OP_MAX_ENUM;
  const VkSamplerAddressMode address =
      depthCompare ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = address;
  info.addressModeV = address;
  info.addressModeW = address;
  info.compareEnable = depthCompare ? VK_TRUE : VK_FALSE;
  info.compareOp = depthCompare ? compare : VK_COMPARE_OP_NEVER;
  info.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  info.maxLod = 0.0f;
  HP_VK_CHECK(fn_->vkCreateSampler(device_, &info, nullptr, &sampler_));
  try {
    ctx.setName(VK_OBJECT_TYPE_SAMPLER, reinterpret_cast<std::uint64_t>(sampler_), name);
  } catch (...) {
    fn_->vkDestroySampler(device_, sampler_, nullptr);
    throw;
  }
}

Sampler::~Sampler() {
  if (sampler_) fn_->vkDestroySampler(device_, sampler_, nullptr);
}

Sampler::Sampler(Sampler&& other) noexcept { *this = std::move(other); }

Sampler& Sampler::operator=(Sampler&& other) noexcept {
  if (this != &other) {
    if (sampler_) fn_->vkDestroySampler(device_, sampler_, nullptr);
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
  }
  return *this;
}
}  // namespace hp::vk
