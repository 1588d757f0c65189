#include "samples/viewer/swapchain.h"

#include <algorithm>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "engine/vk/fault_injection.h"

namespace hp::viewer {
namespace {
constexpr VkImageUsageFlags kUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice gpu, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  HP_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  HP_VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(gpu, surface, &count, formats.data()));
  if (formats.empty()) throw Error("the window's surface offers no formats");
  for (const auto& f : formats)
    if ((f.format == VK_FORMAT_B8G8R8A8_SRGB || f.format == VK_FORMAT_R8G8B8A8_SRGB) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
      return f;
  return formats[0];  // colours then differ slightly from `render`'s PNGs; still a working window
}

VkPresentModeKHR choosePresentMode(VkPhysicalDevice gpu, VkSurfaceKHR surface) {
  std::uint32_t count = 0;
  HP_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  HP_VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(gpu, surface, &count, modes.data()));
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;  // always supported
}

Swapchain::Status statusOf(VkResult r, const char* call) {
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return Swapchain::Status::OutOfDate;
  if (r == VK_SUBOPTIMAL_KHR) return Swapchain::Status::Suboptimal;
  vk::check(r, call);  // anything else but success throws, naming the call (device loss included)
  return Swapchain::Status::Ok;
}
}  // namespace

Swapchain::Swapchain(const vk::Context& ctx, VkSurfaceKHR surface, VkExtent2D framebuffer)
    : ctx_(ctx), surface_(surface) {
  try {
    VkBool32 presents = VK_FALSE;
    HP_VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physicalDevice(), ctx.queueFamily(), surface, &presents));
    if (!presents)
      throw Error(std::string(ctx.properties().deviceName) + " cannot present to this window from queue family " +
                  std::to_string(ctx.queueFamily()) + "; choose another device with --device");
    format_ = chooseFormat(ctx.physicalDevice(), surface);
    mode_ = choosePresentMode(ctx.physicalDevice(), surface);
    create(framebuffer);
  } catch (...) {
    destroyImages();
    if (swapchain_) vkDestroySwapchainKHR(ctx.device(), swapchain_, nullptr);
    vkDestroySurfaceKHR(ctx.instance(), surface_, nullptr);
    throw;
  }
}

Swapchain::~Swapchain() {
  destroyImages();
  if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
  vkDestroySurfaceKHR(ctx_.instance(), surface_, nullptr);
}

void Swapchain::destroyImages() {
  for (VkImageView v : views_) vkDestroyImageView(ctx_.device(), v, nullptr);
  for (VkSemaphore s : rendered_) vkDestroySemaphore(ctx_.device(), s, nullptr);
  views_.clear();
  rendered_.clear();
  images_.clear();
}

void Swapchain::recreate(VkExtent2D framebuffer) {
  destroyImages();
  create(framebuffer);
}

void Swapchain::create(VkExtent2D framebuffer) {
  VkSurfaceCapabilitiesKHR caps;
  HP_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physicalDevice(), surface_, &caps));
  if ((caps.supportedUsageFlags & kUsage) != kUsage)
    throw Error("the window's surface does not allow colour attachment + transfer use of its images");
  extent_ = caps.currentExtent;
  if (extent_.width == 0xFFFFFFFFu) {  // the surface takes the swapchain's size
    extent_.width = std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  std::uint32_t count = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) count = std::min(count, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = count;
  info.imageFormat = format_.format;
  info.imageColorSpace = format_.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = kUsage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode = mode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR next = VK_NULL_HANDLE;
  HP_VK_CHECK(vkCreateSwapchainKHR(ctx_.device(), &info, nullptr, &next));
  if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
  swapchain_ = next;
  const std::string tag = "viewer swapchain " + std::to_string(generation_++);
  ctx_.setName(VK_OBJECT_TYPE_SWAPCHAIN_KHR, reinterpret_cast<std::uint64_t>(swapchain_), tag);

  HP_VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, nullptr));
  images_.resize(count);
  HP_VK_CHECK(vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, images_.data()));
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::string name = tag + " image " + std::to_string(i);
    ctx_.setName(VK_OBJECT_TYPE_IMAGE, reinterpret_cast<std::uint64_t>(images_[i]), name);
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = images_[i];
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format_.format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    HP_VK_CHECK(vkCreateImageView(ctx_.device(), &vi, nullptr, &view));
    views_.push_back(view);
    ctx_.setName(VK_OBJECT_TYPE_IMAGE_VIEW, reinterpret_cast<std::uint64_t>(view), name + " view");
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s = VK_NULL_HANDLE;
    HP_VK_CHECK(vkCreateSemaphore(ctx_.device(), &si, nullptr, &s));
    rendered_.push_back(s);
    ctx_.setName(VK_OBJECT_TYPE_SEMAPHORE, reinterpret_cast<std::uint64_t>(s), name + " rendered");
  }
}

Swapchain::Status Swapchain::acquire(VkSemaphore signal, std::uint32_t& image) {
  return statusOf(vkAcquireNextImageKHR(ctx_.device(), swapchain_, UINT64_MAX, signal, VK_NULL_HANDLE, &image),
                  "vkAcquireNextImageKHR");
}

Swapchain::Status Swapchain::present(std::uint32_t image) {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &rendered_.at(image);
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &image;
  // A fault armed for the present (vk::armFault: tests inject VK_ERROR_OUT_OF_DATE_KHR) is seen like the
  // driver's own result; a present's semaphore wait happens whatever it returns, so that is faithful. Not
  // so for an acquire, whose semaphore would be signalled behind the fault's back: never injected there.
  return statusOf(vk::injectFault("vkQueuePresentKHR", vkQueuePresentKHR(ctx_.queue(), &info)), "vkQueuePresentKHR");
}
}  // namespace hp::viewer
