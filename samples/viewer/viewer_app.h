#pragma once
// Contract: `hairpipe view`: a window showing the whole pipeline live (simulate, tessellate,
// interpolate, opacity shadows, head, the hair raster `render` uses, tonemap) through HairSystem
// (hp::Renderer + one hp::HairInstance) with two frames in flight, the Dear ImGui panel over it and the
// mouse/key controls of view_state.h. Each frame is blitted from hairpipe's offscreen display image
// into the swapchain image, the panel drawn on top, then presented. A resized or minimised window
// (zero-size framebuffer: it waits for events) and an out-of-date or suboptimal swapchain recreate the
// swapchain and targets. A lost device (vk::DeviceLost) is destroyed with everything on it and the
// viewer goes on with a new one (same window and settings; the hair restarts from rest), saying so on
// stderr; lost 3 times in a row without a frame drawn, it gives up. Other Vulkan failures surface as
// hp::Error (a message and exit code 1 from the tool, with everything destroyed in order). With
// `frames` > 0 it stops after that many frames; `screenshot` then holds the last frame's swapchain image
// (panel included), written atomically. For tests: `resizeAt` resizes the window at that frame,
// `minimiseAt` minimises it for `minimiseSeconds`, `faults` inject Vulkan results (vk::armFault).
#include <optional>
#include <string>
#include <vector>

#include "engine/core/hair/hair_asset.h"
#include "samples/cli/scene_options.h"
#include "samples/tools/render_job.h"

namespace hp::viewer {
// Armed (vk::armFault) at the start of frame `frame`, or later once the fault before it has fired.
struct ScriptedFault {
  std::uint32_t frame = 0;
  std::string call;
  VkResult result = VK_SUCCESS;
};

struct ViewerOptions {
  cli::SceneOptions scene;           // device and validation
  RenderRequest request;             // scene (camera, light, size, material, raster...), look, opacity
  std::uint32_t frames = 0;          // 0: until the window closes
  std::string screenshot;
  std::optional<std::uint32_t> resizeAt;
  VkExtent2D resizeTo{0, 0};
  std::optional<std::uint32_t> minimiseAt;
  double minimiseSeconds = 0.0;
  std::vector<ScriptedFault> faults;
  bool panel = true;
};

struct ViewerReport {
  std::uint32_t frames = 0;
  std::uint32_t swapchainRecreations = 0;
  std::uint32_t minimisedWaits = 0;  // times the loop waited for a minimised window to come back
  std::uint32_t deviceLosses = 0;    // devices lost (and replaced, unless the run gave up)
  VkExtent2D extent{0, 0};           // the swapchain's at the end
  std::string device;
  std::string raster;
};

ViewerReport runViewer(const ViewerOptions& options, const HairAsset& asset);
}  // namespace hp::viewer
