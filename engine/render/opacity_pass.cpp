#include "engine/render/opacity_pass.h"

#include <cmath>
#include <string>

#include "engine/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/opacity.h"

namespace hp::render {
namespace {
constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
const vk::Binding kStrandBindings[] = {
    {gpu::OPACITY_BINDING_POSITIONS, kStorage, kVertex},
    {gpu::OPACITY_BINDING_LIGHT, kStorage, kVertex},
};
const vk::Binding kHeadBindings[] = {
    {gpu::OPACITY_BINDING_POSITIONS, kStorage, kVertex},
    {gpu::OPACITY_BINDING_INDICES, kStorage, kVertex},
    {gpu::OPACITY_BINDING_LIGHT, kStorage, kVertex},
};
constexpr VkBufferUsageFlags kMeshUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

vk::GraphicsPipeline makePipeline(const vk::Context& ctx, VkDescriptorSetLayout layout, VkFormat format, bool head) {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = head ? "opacity_head.vert" : "opacity.vert";
  desc.fragmentShader = "opacity.frag";
  desc.colorFormats.assign(gpu::OPACITY_TARGETS, format);
  desc.blend = vk::BlendMode::Additive;  // order-independent sums, no depth test
  desc.topology = head ? VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST : VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
  desc.sets = {layout};
  desc.pushSize = sizeof(gpu::OpacityPush);
  desc.name = head ? "opacity head" : "opacity strands";
  return vk::GraphicsPipeline(ctx, desc);
}

VkRenderingAttachmentInfo sliceAttachment(VkImageView view) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
  return a;
}
}  // namespace

OpacityPass::OpacityPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const HeadMesh& head,
                         const vk::Buffer& lightSpace, const OpacitySettings& settings)
    : ctx_(ctx), settings_(settings), lightSpace_(&lightSpace) {
  settings_.validate();
  vk::ImageDesc desc;
  desc.width = desc.height = settings_.resolution;
  desc.layers = gpu::OPACITY_TARGETS;
  desc.format = settings_.format;
  desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.name = "opacity maps";
  image_ = vk::Image(ctx, desc);
  sampler_ = vk::Sampler(ctx, "opacity sampler");
  clearImage();
  uploadHead(head);
  bind(strands);
  strandPipeline_ = makePipeline(ctx, strandSets_.front().layout(), settings_.format, false);
  headPipeline_ = makePipeline(ctx, headSet_.layout(), settings_.format, true);
}

void OpacityPass::clearImage() {
  vk::submitAndWait(ctx_, [&](VkCommandBuffer cmd) {
    vk::imageBarrier(cmd, image_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::Undefined,
                     vk::ImageUse::TransferDst, gpu::OPACITY_TARGETS);
    const VkClearColorValue zero{{0.0f, 0.0f, 0.0f, 0.0f}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, gpu::OPACITY_TARGETS};
    vkCmdClearColorImage(cmd, image_.handle(), vk::imageLayout(vk::ImageUse::TransferDst), &zero, 1, &range);
    vk::imageBarrier(cmd, image_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferDst,
                     vk::ImageUse::FragmentSampled, gpu::OPACITY_TARGETS);
  }, "clear opacity maps");
}

void OpacityPass::uploadHead(const HeadMesh& head) {
  headIndexCount_ = static_cast<std::uint32_t>(head.indices.size());
  for (std::uint32_t i : head.indices)
    if (i >= head.positions.size()) throw Error("head mesh: index " + std::to_string(i) + " is out of range");
  std::vector<glm::vec4> positions;
  for (const glm::vec3& p : head.positions) positions.emplace_back(p, 1.0f);
  // Placeholders keep the descriptors valid for a head-less asset (nothing is drawn then).
  if (positions.empty()) positions.emplace_back(0.0f);
  std::vector<std::uint32_t> indices = head.indices;
  if (indices.empty()) indices.push_back(0);
  headPositions_ = vk::Buffer(ctx_, positions.size() * sizeof(glm::vec4), kMeshUsage, vk::MemoryKind::DeviceLocal,
                              "opacity head positions");
  headIndices_ = vk::Buffer(ctx_, indices.size() * sizeof(std::uint32_t), kMeshUsage, vk::MemoryKind::DeviceLocal,
                            "opacity head indices");
  vk::upload<glm::vec4>(ctx_, headPositions_, positions, vk::BufferUse::VertexRead);
  vk::upload<std::uint32_t>(ctx_, headIndices_, indices, vk::BufferUse::VertexRead);
  headSet_ = vk::DescriptorSet(ctx_, kHeadBindings, "opacity head");
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_POSITIONS, headPositions_.handle());
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_INDICES, headIndices_.handle());
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_LIGHT, lightSpace_->handle());
}

void OpacityPass::bind(const compute::StrandBuffers& strands) {
  strands_ = &strands;
  std::vector<vk::DescriptorSet> sets;
  for (const auto& chunk : strands.chunks()) {
    vk::DescriptorSet set(ctx_, kStrandBindings, "opacity strands [chunk " + std::to_string(sets.size()) + "]");
    set.writeStorageBuffer(gpu::OPACITY_BINDING_POSITIONS, chunk.positions.handle());
    set.writeStorageBuffer(gpu::OPACITY_BINDING_LIGHT, lightSpace_->handle());
    sets.push_back(std::move(set));
  }
  strandSets_ = std::move(sets);
}

void OpacityPass::record(VkCommandBuffer cmd, const glm::mat4& headToWorld) const {
  VkRenderingAttachmentInfo attachments[gpu::OPACITY_TARGETS];
  for (std::uint32_t t = 0; t < gpu::OPACITY_TARGETS; ++t) attachments[t] = sliceAttachment(image_.layerView(t));
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, image_.extent()};
  info.layerCount = 1;
  info.colorAttachmentCount = gpu::OPACITY_TARGETS;
  info.pColorAttachments = attachments;
  vkCmdBeginRendering(cmd, &info);

  const std::uint32_t q = strands_->layout().verticesPerStrand;
  gpu::OpacityPush push{};
  push.opacity = settings_.footprint ? 1.0f : settings_.strandOpacity;
  push.verticesPerStrand = q;
  push.footprint = glm::vec4(settings_.strandWidth, settings_.tipWidthFraction, 1.0f / float(settings_.resolution),
                             settings_.footprint ? 1.0f : 0.0f);
  for (std::size_t c = 0; c < strandSets_.size(); ++c) {
    strandPipeline_.bind(cmd, strandSets_[c].set(), image_.extent());
    strandPipeline_.push(cmd, push);
    vkCmdDraw(cmd, strands_->chunks()[c].range.strandCount * (q - 1) * 2, 1, 0, 0);
  }
  if (headIndexCount_ > 0 && settings_.headOpacity > 0.0f) {
    push.headToWorld = headToWorld;
    push.opacity = settings_.headOpacity;
    headPipeline_.bind(cmd, headSet_.set(), image_.extent());
    headPipeline_.push(cmd, push);
    vkCmdDraw(cmd, headIndexCount_, 1, 0, 0);
  }
  vkCmdEndRendering(cmd);
}
}  // namespace hp::render
