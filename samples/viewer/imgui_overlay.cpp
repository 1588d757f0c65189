#include "samples/viewer/imgui_overlay.h"

#include <algorithm>
#include <cstring>
#include <span>
#include <string>

#include "engine/vk/transfer.h"
#include "shaders/shared/overlay.h"

namespace hp::viewer {
namespace {
static_assert(sizeof(ImDrawVert) == gpu::OVERLAY_VERTEX_WORDS * 4, "ImDrawVert must be pos, uv, packed colour");
static_assert(sizeof(ImDrawIdx) == 2 || sizeof(ImDrawIdx) == 4);
constexpr VkIndexType kIndexType = sizeof(ImDrawIdx) == 2 ? VK_INDEX_TYPE_UINT16 : VK_INDEX_TYPE_UINT32;

const vk::Binding kBindings[] = {
    {gpu::OVERLAY_BINDING_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT},
    {gpu::OVERLAY_BINDING_TEXTURE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};

vk::Image uploadFont(const vk::Context& ctx) {
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  ImGui::GetIO().Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  vk::ImageDesc desc;
  desc.width = std::uint32_t(width);
  desc.height = std::uint32_t(height);
  desc.format = VK_FORMAT_R8G8B8A8_UNORM;
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.name = "viewer ui font atlas";
  vk::Image image(ctx, desc);
  vk::uploadImage(ctx, image, std::as_bytes(std::span(pixels, std::size_t(width) * height * 4)),
                  vk::ImageUse::FragmentSampled);
  return image;
}

VkRect2D clipRect(const ImVec4& clip, const ImVec2& origin, VkExtent2D extent) {
  const float x0 = std::clamp(clip.x - origin.x, 0.0f, float(extent.width));
  const float y0 = std::clamp(clip.y - origin.y, 0.0f, float(extent.height));
  const float x1 = std::clamp(clip.z - origin.x, 0.0f, float(extent.width));
  const float y1 = std::clamp(clip.w - origin.y, 0.0f, float(extent.height));
  return {{std::int32_t(x0), std::int32_t(y0)},
          {std::uint32_t(std::max(0.0f, x1 - x0)), std::uint32_t(std::max(0.0f, y1 - y0))}};
}
}  // namespace

ImGuiOverlay::ImGuiOverlay(const vk::Context& ctx, VkFormat colorFormat, std::uint32_t framesInFlight)
    : ctx_(ctx), font_(uploadFont(ctx)), sampler_(ctx, "viewer ui sampler") {
  ImGui::GetIO().Fonts->SetTexID(reinterpret_cast<ImTextureID>(std::uintptr_t(1)));  // the only texture
  for (std::uint32_t i = 0; i < framesInFlight; ++i) {
    Slot slot{{}, {}, vk::DescriptorSet(ctx, kBindings, "viewer ui slot " + std::to_string(i))};
    slot.set.writeSampledImage(gpu::OVERLAY_BINDING_TEXTURE, font_.view(), sampler_.handle());
    slots_.push_back(std::move(slot));
    reserve(slots_.back(), i, 64 * 1024, 16 * 1024);
  }
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "overlay.vert";
  desc.fragmentShader = "overlay.frag";
  desc.colorFormats = {colorFormat};
  desc.blend = vk::BlendMode::Alpha;
  desc.sets = {slots_[0].set.layout()};
  desc.pushSize = sizeof(gpu::OverlayPush);
  desc.name = "viewer ui";
  pipeline_ = vk::GraphicsPipeline(ctx, desc);
}

void ImGuiOverlay::reserve(Slot& slot, std::uint32_t index, std::size_t vertexBytes, std::size_t indexBytes) {
  const std::string name = "viewer ui slot " + std::to_string(index);
  if (!slot.vertices || slot.vertices.size() < vertexBytes) {
    slot.vertices = vk::Buffer(ctx_, std::max<std::size_t>(vertexBytes * 2, 4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                               vk::MemoryKind::Upload, name + " vertices");
    slot.set.writeStorageBuffer(gpu::OVERLAY_BINDING_VERTICES, slot.vertices.handle());
  }
  if (!slot.indices || slot.indices.size() < indexBytes)
    slot.indices = vk::Buffer(ctx_, std::max<std::size_t>(indexBytes * 2, 4), VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                              vk::MemoryKind::Upload, name + " indices");
}

void ImGuiOverlay::draw(VkCommandBuffer cmd, std::uint32_t slotIndex, const ImDrawData& data, VkExtent2D extent) {
  if (data.TotalVtxCount == 0 || extent.width == 0 || extent.height == 0) return;
  Slot& slot = slots_.at(slotIndex);
  reserve(slot, slotIndex, std::size_t(data.TotalVtxCount) * sizeof(ImDrawVert),
          std::size_t(data.TotalIdxCount) * sizeof(ImDrawIdx));
  auto* vtx = static_cast<std::byte*>(slot.vertices.mapped());
  auto* idx = static_cast<std::byte*>(slot.indices.mapped());
  for (int n = 0; n < data.CmdListsCount; ++n) {  // host-coherent memory: visible at submission
    const ImDrawList& list = *data.CmdLists[n];
    std::memcpy(vtx, list.VtxBuffer.Data, std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert));
    std::memcpy(idx, list.IdxBuffer.Data, std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx));
    vtx += std::size_t(list.VtxBuffer.Size) * sizeof(ImDrawVert);
    idx += std::size_t(list.IdxBuffer.Size) * sizeof(ImDrawIdx);
  }
  pipeline_.bind(cmd, slot.set.set(), extent);
  vkCmdBindIndexBuffer(cmd, slot.indices.handle(), 0, kIndexType);
  gpu::OverlayPush push;
  // ImGui's y grows down; hairpipe's pipelines flip the viewport so clip y grows up (vk::GraphicsPipeline::bind).
  push.scale = {2.0f / data.DisplaySize.x, -2.0f / data.DisplaySize.y};
  push.translate = {-1.0f - data.DisplayPos.x * push.scale.x, 1.0f - data.DisplayPos.y * push.scale.y};
  pipeline_.push(cmd, push);
  std::uint32_t vertexBase = 0, indexBase = 0;
  for (int n = 0; n < data.CmdListsCount; ++n) {
    const ImDrawList& list = *data.CmdLists[n];
    for (const ImDrawCmd& c : list.CmdBuffer) {
      if (c.UserCallback) continue;  // the panel registers none
      const VkRect2D scissor = clipRect(c.ClipRect, data.DisplayPos, extent);
      if (scissor.extent.width == 0 || scissor.extent.height == 0) continue;
      vkCmdSetScissor(cmd, 0, 1, &scissor);
      vkCmdDrawIndexed(cmd, c.ElemCount, 1, indexBase + c.IdxOffset, std::int32_t(vertexBase + c.VtxOffset), 0);
    }
    vertexBase += std::uint32_t(list.VtxBuffer.Size);
    indexBase += std::uint32_t(list.IdxBuffer.Size);
  }
}
}  // namespace hp::viewer
