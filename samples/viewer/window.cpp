#include "samples/viewer/window.h"

#include "engine/core/error.h"
#include "engine/vk/check.h"

namespace hp::viewer {
namespace {
std::string glfwMessage() {
  const char* text = nullptr;
  glfwGetError(&text);
  return text ? text : "unknown GLFW error";
}
}  // namespace

Window::Window(std::uint32_t width, std::uint32_t height, const std::string& title) {
  if (glfwInit() != GLFW_TRUE)
    throw Error("cannot open a window: " + glfwMessage() + " (is DISPLAY set? under CI run it in Xvfb)");
  if (glfwVulkanSupported() != GLFW_TRUE) {
    glfwTerminate();
    throw Error("GLFW found no Vulkan loader for windows");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = glfwMessage();
    glfwTerminate();
    throw Error("cannot create a " + std::to_string(width) + "x" + std::to_string(height) + " window: " + why);
  }
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
  std::uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw Error("GLFW cannot make Vulkan surfaces here: " + glfwMessage());
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  const VkResult r = glfwCreateWindowSurface(instance, window_, nullptr, &surface);
  if (r != VK_SUCCESS) throw Error("cannot create a Vulkan surface for the window (" + std::string(vk::resultName(r)) + ")");
  return surface;
}

bool Window::minimised() const {
  const VkExtent2D fb = framebufferSize();
  return fb.width == 0 || fb.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED) == GLFW_TRUE ||
         glfwGetTime() < minimisedUntil_;
}

void Window::waitWhileMinimised() {
  while (minimised() && !shouldClose()) {
    const double forced = minimisedUntil_ - glfwGetTime();
    glfwWaitEventsTimeout(forced > 0.0 ? forced : 0.5);  // a restore or resize event ends the wait early
  }
  if (minimisedUntil_ >= 0.0) {
    minimisedUntil_ = -1.0;
    glfwRestoreWindow(window_);
  }
}

void Window::minimiseFor(double seconds) {
  glfwIconifyWindow(window_);
  minimisedUntil_ = glfwGetTime() + seconds;
}

VkExtent2D Window::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {std::uint32_t(std::max(w, 0)), std::uint32_t(std::max(h, 0))};
}
}  // namespace hp::viewer
