#pragma once
// Contract: one GLFW window without a client API (Vulkan draws into it), and GLFW itself, initialised
// and terminated with it (one Window per process). Input goes to the callbacks the owner installs with
// glfwSetWindowUserPointer on handle(); the Dear ImGui GLFW backend chains to them. Throws hp::Error
// when GLFW cannot start (no display: say so) or has no Vulkan loader. A minimised window (iconified,
// or a zero-size framebuffer, as some platforms report it) is not drawn: waitWhileMinimised() blocks,
// handling events, until it is back or closed.
#include "hairpipe_volk.h"

#include <GLFW/glfw3.h>

#include <string>
#include <vector>

namespace hp::viewer {
class Window {
 public:
  Window(std::uint32_t width, std::uint32_t height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  // The instance extensions GLFW needs to make a surface on this platform.
  static std::vector<std::string> requiredInstanceExtensions();
  VkSurfaceKHR createSurface(VkInstance instance) const;
  VkExtent2D framebufferSize() const;  // 0 x 0 while minimised on some platforms
  bool shouldClose() const { return glfwWindowShouldClose(window_); }
  bool minimised() const;
  void waitWhileMinimised();
  // Testing: iconifies the window and counts it minimised for `seconds`, then restores it; Xvfb has no
  // window manager, so there the iconify alone changes nothing.
  void minimiseFor(double seconds);

 private:
  GLFWwindow* window_ = nullptr;
  double minimisedUntil_ = -1.0;  // glfwGetTime() until which minimiseFor() holds it minimised
};
}  // namespace hp::viewer
