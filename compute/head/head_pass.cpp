#include "compute/head/head_pass.h"

#include "engine/core/error.h"
#include "engine/vk/application_attachments.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/render.h"

namespace hp::render {
namespace {
constexpr VkBufferUsageFlags kHeadUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
const vk::Binding kHeadBindings[] = {
    {gpu::RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT},
    {gpu::RENDER_BINDING_POSITIONS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_TANGENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_ATTRIBUTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_OPACITY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT},
    {gpu::RENDER_BINDING_HEAD_SHADOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT},
    {gpu::RENDER_BINDING_LIGHT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT},
    {gpu::RENDER_BINDING_SKIN_TRANSFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
};

// xyz from v, w from `w` (or 1 where it is empty).
std::vector<glm::vec4> asVec4(const std::vector<glm::vec3>& v, const std::vector<float>& w = {}) {
  std::vector<glm::vec4> out;
  out.reserve(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out.emplace_back(v[i], w.empty() ? 1.0f : w[i]);
  return out;
}
}  // namespace

HeadPass::HeadPass(const vk::Context& ctx, const HeadMesh& mesh, std::shared_ptr<const SkinTransferBuffer> transfer,
                   const vk::Buffer& frameBlock, const ShadowInputs& shadows, const hairpipe::AttachmentFormats& formats,
                   vk::PipelineLibrary* library)
    : indexCount_(static_cast<std::uint32_t>(mesh.indices.size())), transfer_(std::move(transfer)) {
  if (mesh.normals.size() != mesh.positions.size()) throw Error("head mesh: one normal per position is required");
  if (!mesh.scalp.empty() && mesh.scalp.size() != mesh.positions.size())
    throw Error("head mesh: one scalp weight per position is required");
  for (std::uint32_t i : mesh.indices)
    if (i >= mesh.positions.size()) throw Error("head mesh: index " + std::to_string(i) + " is out of range");
  set_ = vk::DescriptorSet(ctx, kHeadBindings, "head");
  set_.writeBuffer(gpu::RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, frameBlock.handle(), 0,
                   sizeof(gpu::RenderFrame));
  set_.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);  // hair shadows
  set_.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
  set_.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "head.vert";
  desc.fragmentShader = "head.frag";
  vk::setApplicationAttachments(desc, formats);
  desc.depthTest = desc.depthWrite = true;
  desc.cullMode = VK_CULL_MODE_BACK_BIT;
  desc.sets = {set_.layout()};
  desc.pushSize = sizeof(glm::mat4);
  desc.name = "head";
  desc.fragmentSpecialization = {1u};  // HEAD_LIGHT_LOOP
  pipeline_ = vk::makeGraphicsPipeline(ctx, library, desc);
  desc.name = "head (one light)";
  desc.fragmentSpecialization = {0u};
  oneLightPipeline_ = vk::makeGraphicsPipeline(ctx, library, desc);
  if (empty()) return;
  positions_ = vk::Buffer(ctx, mesh.positions.size() * sizeof(glm::vec4), kHeadUsage, vk::MemoryKind::DeviceLocal, "head positions");
  normals_ = vk::Buffer(ctx, mesh.normals.size() * sizeof(glm::vec4), kHeadUsage, vk::MemoryKind::DeviceLocal, "head normals");
  indices_ = vk::Buffer(ctx, mesh.indices.size() * sizeof(std::uint32_t), kHeadUsage, vk::MemoryKind::DeviceLocal, "head indices");
  vk::upload<glm::vec4>(ctx, positions_, asVec4(mesh.positions), vk::BufferUse::VertexRead);
  // The normal's w carries the scalp weight: hair colour shows through where hair grows.
  std::vector<float> scalp = mesh.scalp.empty() ? std::vector<float>(mesh.positions.size(), 0.0f) : mesh.scalp;
  vk::upload<glm::vec4>(ctx, normals_, asVec4(mesh.normals, scalp), vk::BufferUse::VertexRead);
  vk::upload<std::uint32_t>(ctx, indices_, mesh.indices, vk::BufferUse::VertexRead);
  if (!transfer_ || transfer_->vertexCount() != mesh.positions.size())
    throw Error("head mesh: a skin transfer of its " + std::to_string(mesh.positions.size()) + " vertices is required");
  set_.writeStorageBuffer(gpu::RENDER_BINDING_SKIN_TRANSFER, transfer_->buffer().handle());
  set_.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, positions_.handle());
  set_.writeStorageBuffer(gpu::RENDER_BINDING_TANGENTS, normals_.handle());
  set_.writeStorageBuffer(gpu::RENDER_BINDING_ATTRIBUTES, indices_.handle());
}

void HeadPass::draw(VkCommandBuffer cmd, VkExtent2D extent, const glm::mat4& headToWorld, std::uint32_t frameOffset,
                    bool oneLight) const {
  if (empty()) return;
  const vk::GraphicsPipeline& pipeline = oneLight ? *oneLightPipeline_ : *pipeline_;
  pipeline.bind(cmd, set_.set(), extent, frameOffset);
  pipeline.push(cmd, headToWorld);
  pipeline.draw(cmd, indexCount_);
}
}  // namespace hp::render
