#pragma once
// Contract: draws Dear ImGui's draw data with hairpipe's own Vulkan helpers (dynamic rendering, named
// objects, the engine/vk barriers), in place of Debian's imgui_impl_vulkan 1.86, which needs a
// VkRenderPass. Construction uploads the font atlas (blocking, outside the frame loop). Per frame slot
// (framesInFlight of them) a host-visible vertex and index buffer, grown when a frame needs more: a
// slot is only rewritten after the caller waited for the frame that last used it. draw() goes inside a
// vkCmdBeginRendering on one colour attachment of `colorFormat`.
#include <imgui.h>

#include <cstdint>
#include <vector>

#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

namespace hp::viewer {
class ImGuiOverlay {
 public:
  ImGuiOverlay(const vk::Context& ctx, VkFormat colorFormat, std::uint32_t framesInFlight);
  // Copies the draw data into the slot's buffers (before recording) and records the draws.
  void draw(VkCommandBuffer cmd, std::uint32_t slot, const ImDrawData& data, VkExtent2D extent);

 private:
  struct Slot {
    vk::Buffer vertices;
    vk::Buffer indices;
    vk::DescriptorSet set;
  };
  void reserve(Slot& slot, std::uint32_t index, std::size_t vertexBytes, std::size_t indexBytes);

  const vk::Context& ctx_;
  vk::Image font_;
  vk::Sampler sampler_;
  std::vector<Slot> slots_;
  vk::GraphicsPipeline pipeline_;
};
}  // namespace hp::viewer
