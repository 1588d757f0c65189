#pragma once
// Contract: the window's surface and swapchain: an sRGB colour format when the surface offers one,
// images usable as colour attachment, blit destination and copy source (the screenshot), a
// low-latency present mode (mailbox, else immediate, else FIFO), and one "rendered" semaphore per
// image for the present to wait on. acquire()/present() report out of date or suboptimal instead of
// throwing, and recreate() rebuilds everything for a new framebuffer size; the caller waits for the
// device to be idle before recreate() and the destructor. Other failures throw hp::Error.
#include "hairpipe_volk.h"

#include <cstdint>
#include <vector>

namespace hp::vk {
class Context;
}

namespace hp::viewer {
class Swapchain {
 public:
  enum class Status { Ok, Suboptimal, OutOfDate };

  // Takes ownership of `surface`. Throws hp::Error when the device's queue cannot present to it.
  Swapchain(const vk::Context& ctx, VkSurfaceKHR surface, VkExtent2D framebuffer);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  void recreate(VkExtent2D framebuffer);
  Status acquire(VkSemaphore signal, std::uint32_t& image);
  Status present(std::uint32_t image);

  VkFormat format() const { return format_.format; }
  VkExtent2D extent() const { return extent_; }
  VkImage image(std::uint32_t i) const { return images_.at(i); }
  VkImageView view(std::uint32_t i) const { return views_.at(i); }
  VkSemaphore rendered(std::uint32_t i) const { return rendered_.at(i); }

 private:
  void create(VkExtent2D framebuffer);
  void destroyImages();

  const vk::Context& ctx_;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkSurfaceFormatKHR format_{};
  VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
  VkExtent2D extent_{};
  std::uint32_t generation_ = 0;  // in the debug names, one per recreation
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkSemaphore> rendered_;
};
}  // namespace hp::viewer
