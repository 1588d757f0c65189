#pragma once
// Contract: `hairpipe view`: a window showing the whole pipeline live (simulate, tessellate,
// interpolate, opacity shadows, head, the hair raster `render` uses, tonemap) through HairSystem
// (hp::Renderer + one hp::HairInstance) with two frames in flight, the Dear ImGui panel over it and the
// mouse/key controls of view_state.h. Each frame is blitted from hairpipe's offscreen display image
// into the swapchain image, the panel drawn on top, then presented. A resized or minimised window
// (zero-size framebuffer: it waits for events) and an out-of-date or suboptimal swapchain recreate the
// swapchain and targets; device loss and other Vulkan failures surface as hp::Error (a message and
// exit code 1 from the tool, with everything destroyed in order). With `frames` > 0 it stops after
// that many frames; `screenshot` then holds the last frame's swapchain image (panel included), written
// atomically. `resizeAt` resizes the window at that frame (a scripted resize for tests).
#include <optional>
#include <string>

#include "engine/hair/hair_asset.h"
#include "samples/cli/scene_options.h"
#include "samples/tools/render_job.h"

namespace hp::viewer {
struct ViewerOptions {
  cli::SceneOptions scene;           // device and validation
  RenderRequest request;             // scene (camera, light, size, material, raster...), look, opacity
  std::uint32_t frames = 0;          // 0: until the window closes
  std::string screenshot;
  std::optional<std::uint32_t> resizeAt;
  VkExtent2D resizeTo{0, 0};
  bool panel = true;
};

struct ViewerReport {
  std::uint32_t frames = 0;
  std::uint32_t swapchainRecreations = 0;
  VkExtent2D extent{0, 0};           // the swapchain's at the end
  std::string device;
  std::string raster;
};

ViewerReport runViewer(const ViewerOptions& options, const HairAsset& asset);
}  // namespace hp::viewer
