#pragma once
// Contract: a 2D (array) image with device-local memory (sub-allocated from the Context's MemoryPool, or
// dedicated where the driver asks for it) and views, move-only. view() covers all
// layers (2D, or 2D_ARRAY when layers > 1 or arrayView); layerView(i) is a 2D view of one layer for attachments;
// groupView(g) a 2D_ARRAY view of layers [g x groupLayers, (g + 1) x groupLayers) when groupLayers is set
// (a storage view that touches one group only).
// Layout tracking is the caller's job, through the named transitions in barriers.h.
#include "hairpipe_volk.h"

#include <cstdint>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "engine/vk/memory_pool.h"

namespace hp::vk {
class Context;

struct ImageDesc {
  std::uint32_t width = 1;
  std::uint32_t height = 1;
  std::uint32_t layers = 1;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageUsageFlags usage = 0;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  std::string name;
  bool arrayView = false;  // view() is 2D_ARRAY even for one layer (for shaders that declare an array)
  std::uint32_t groupLayers = 0;  // > 0: a groupView per this many layers (layers must be a multiple)
};

class Image {
 public:
  Image() = default;
  Image(const Context& ctx, const ImageDesc& desc);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkImageView layerView(std::uint32_t layer) const { return layerViews_.at(layer); }
  VkImageView groupView(std::uint32_t group) const { return groupViews_.at(group); }
  const ImageDesc& desc() const { return desc_; }
  VkExtent2D extent() const { return {desc_.width, desc_.height}; }
  VkImageAspectFlags aspect() const;
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

 private:
  void release();
  VkImageView createView(const Context& ctx, VkImageViewType type, std::uint32_t firstLayer,
                         std::uint32_t layerCount, const std::string& name);
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkImage image_ = VK_NULL_HANDLE;
  MemoryPool* pool_ = nullptr;
  MemoryAllocation memory_;
  std::shared_ptr<std::atomic<std::int64_t>> tally_;  // Context::allocatedBytes
  VkDeviceSize allocated_ = 0;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> layerViews_;
  std::vector<VkImageView> groupViews_;
  ImageDesc desc_;
};

bool isDepthFormat(VkFormat format);        // D16, D32, or a combined D16S8, D24S8 or D32S8
bool hasStencilComponent(VkFormat format);  // the combined ones
bool isIntegerColorFormat(VkFormat format); // a UINT or SINT colour format (a shader writes it integers)
bool isSrgbFormat(VkFormat format);         // an uncompressed SRGB colour format (encoded on write)
std::uint32_t formatBytesPerPixel(VkFormat format);  // for the formats hairpipe reads back

// A sampler with linear filtering (or `filter`: nearest for formats that cannot filter) and clamp-to-edge
// (what every LUT, shadow and tonemap lookup uses), move-only and destroyed with its owner, so a
// constructor that throws after making one cannot leak it. With a compare op it is a depth-compare
// sampler (sampler2DShadow: filtered percentage-closer lookups); its border is opaque white
// (clamp-to-border), so lookups outside a depth map pass the test.
class Sampler {
 public:
  Sampler() = default;
  Sampler(const Context& ctx, const std::string& name, VkFilter filter = VK_FILTER_LINEAR);
  Sampler(const Context& ctx, const std::string& name, VkCompareOp compare);
  ~Sampler();
  Sampler(Sampler&& other) noexcept;
  Sampler& operator=(Sampler&& other) noexcept;
  Sampler(const Sampler&) = delete;
  Sampler& operator=(const Sampler&) = delete;
  VkSampler handle() const { return sampler_; }

 private:
  Sampler(const Context& ctx, const std::string& name, VkFilter filter, VkCompareOp compare);
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkSampler sampler_ = VK_NULL_HANDLE;
};
}  // namespace hp::vk
