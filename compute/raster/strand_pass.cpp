#include "compute/raster/strand_pass.h"

#include "engine/vk/application_attachments.h"
#include "shaders/shared/render.h"

namespace hp::render {
namespace {
constexpr VkShaderStageFlags kBoth = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
const vk::Binding kStrandBindings[] = {
    {gpu::RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, kBoth},
    {gpu::RENDER_BINDING_MARSCHNER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kFragment},
    {gpu::RENDER_BINDING_LUT_M, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_LUT_N0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_LUT_N1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_OPACITY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_HEAD_SHADOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_LIGHT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kFragment},
    {gpu::RENDER_BINDING_POSITIONS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_TANGENTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_ATTRIBUTES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
    {gpu::RENDER_BINDING_BOUNCE_SAMPLES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kVertex},
};

std::shared_ptr<const vk::GraphicsPipeline> makeStrandPipeline(const vk::Context& ctx, vk::PipelineLibrary* library,
                                                         VkDescriptorSetLayout layout,
                                                         const hairpipe::AttachmentFormats& formats, bool lines) {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "strands.vert";
  desc.fragmentShader = "strands.frag";
  vk::setApplicationAttachments(desc, formats);
  desc.depthTest = desc.depthWrite = true;
  // With MSAA the fragment shader writes its coverage as a dithered sample mask (order-independent);
  // without MSAA, coverage is alpha and blends.
  desc.blend = formats.samples != VK_SAMPLE_COUNT_1_BIT ? vk::BlendMode::None : vk::BlendMode::Alpha;
  desc.topology = lines ? VK_PRIMITIVE_TOPOLOGY_LINE_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  desc.sets = {layout};
  desc.pushSize = sizeof(gpu::StrandDrawPush);
  desc.name = lines ? "strand lines" : "strand ribbons";
  return vk::makeGraphicsPipeline(ctx, library, desc);
}
}  // namespace

StrandPass::StrandPass(const vk::Context& ctx, const compute::StrandBuffers& strands,
                       const MarschnerTextures& marschner, const vk::Buffer& frameBlock,
                       const ShadowInputs& shadows, const hairpipe::AttachmentFormats& formats, vk::PipelineLibrary* library)
    : strands_(&strands), samples_(formats.samples) {
  for (const auto& chunk : strands.chunks()) {
    vk::DescriptorSet set(ctx, kStrandBindings, "strands chunk " + std::to_string(sets_.size()));
    set.writeBuffer(gpu::RENDER_BINDING_FRAME, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC, frameBlock.handle(), 0,
                    sizeof(gpu::RenderFrame));
    marschner.writeDescriptors(set, gpu::RENDER_BINDING_MARSCHNER, gpu::RENDER_BINDING_LUT_M,
                               gpu::RENDER_BINDING_LUT_N0, gpu::RENDER_BINDING_LUT_N1);
    set.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, chunk.positions.handle());
    set.writeStorageBuffer(gpu::RENDER_BINDING_TANGENTS, chunk.tangents.handle());
    set.writeStorageBuffer(gpu::RENDER_BINDING_ATTRIBUTES, chunk.attributes.handle());
    set.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
    set.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
    set.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
    set.writeStorageBuffer(gpu::RENDER_BINDING_BOUNCE_SAMPLES, chunk.bounce.handle());
    sets_.push_back(std::move(set));
  }
  ribbons_ = makeStrandPipeline(ctx, library, sets_.front().layout(), formats, false);
  lines_ = makeStrandPipeline(ctx, library, sets_.front().layout(), formats, true);
}

void StrandPass::draw(VkCommandBuffer cmd, VkExtent2D extent, bool lines, std::uint32_t frameOffset,
                      std::uint32_t strandLimit) const {
  const auto& layout = strands_->layout();
  const std::uint32_t perSegment = lines ? gpu::STRAND_VERTICES_PER_LINE : gpu::STRAND_VERTICES_PER_QUAD;
  const vk::GraphicsPipeline& pipeline = lines ? *lines_ : *ribbons_;
  for (std::size_t c = 0; c < sets_.size(); ++c) {
    const auto& range = strands_->chunks()[c].range;
    const std::uint32_t drawn = compute::strandsWithin(range, strandLimit);
    if (drawn == 0) continue;
    pipeline.bind(cmd, sets_[c].set(), extent, frameOffset);
    pipeline.push(cmd, gpu::StrandDrawPush{range.firstStrand, lines ? 1u : 0u, std::uint32_t(samples_), 0u});
    pipeline.draw(cmd, drawn * (layout.verticesPerStrand - 1) * perSegment);
  }
}
}  // namespace hp::render
