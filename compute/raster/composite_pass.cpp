#include "compute/raster/composite_pass.h"

#include <string>

#include "engine/core/error.h"
#include "engine/vk/application_attachments.h"
#include "engine/vk/context.h"

namespace hp::render {
namespace {
const vk::Binding kCompositeBindings[] = {{gpu::COMPOSITE_BINDING_HAIR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {gpu::COMPOSITE_BINDING_NEAR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {gpu::COMPOSITE_BINDING_NEAR_MASK, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT}};
const vk::Binding kVelocityBindings[] = {{gpu::COMPOSITE_BINDING_HAIR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                         {gpu::COMPOSITE_BINDING_NEAR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                         {gpu::COMPOSITE_BINDING_NEAR_MASK, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                         {gpu::COMPOSITE_BINDING_MOTION, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT}};
}  // namespace

CompositePass::CompositePass(const vk::Context& ctx, const hairpipe::AttachmentFormats& formats,
                             const hairpipe::VelocityOutput& velocity, VkPipelineCache cache)
    : sampler_(ctx, "composite sampler", VK_FILTER_NEAREST),
      set_(ctx, kCompositeBindings, "composite"),
      multisampled_(formats.samples != VK_SAMPLE_COUNT_1_BIT),
      velocity_(velocityWrite(ctx, formats, velocity, cache)) {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "composite.vert";
  desc.fragmentShader = "composite.frag";
  vk::setApplicationAttachments(desc, formats);
  desc.blend = vk::BlendMode::Premultiplied;
  desc.sets = {set_.layout()};
  desc.pushSize = sizeof(std::uint32_t);  // which samples (COMPOSITE_*)
  desc.name = "hair composite";
  pipeline_ = vk::GraphicsPipeline(ctx, desc, cache);
}

std::optional<CompositePass::VelocityWrite> CompositePass::velocityWrite(const vk::Context& ctx,
                                                                         const hairpipe::AttachmentFormats& formats,
                                                                         const hairpipe::VelocityOutput& velocity,
                                                                         VkPipelineCache cache) {
  if (velocity.attachment < 0) return std::nullopt;
  if (std::size_t(velocity.attachment) >= formats.otherColors.size())
    throw Error("CompositePass: the velocity attachment is not one of formats.otherColors");
  VelocityWrite w{vk::DescriptorSet(ctx, kVelocityBindings, "composite velocity"), {},
                  {{velocity.scaleX, velocity.scaleY}, {velocity.offsetX, velocity.offsetY}, velocity.minCoverage,
                   std::uint32_t(formats.samples)}};
  const std::uint32_t location = 1 + std::uint32_t(velocity.attachment);  // after hairpipe's colour
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "composite.vert";
  desc.fragmentShader = "composite_velocity_" + std::to_string(location) + ".frag";
  vk::setApplicationAttachments(desc, formats);
  desc.writtenColors = 1u << location;  // the velocity attachment alone, replaced where the hair covers enough
  desc.writtenComponents = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT;  // its other channels are the engine's
  desc.sets = {w.set.layout()};
  desc.pushSize = sizeof(gpu::CompositeVelocityPush);
  desc.name = "hair velocity";
  w.pipeline = vk::GraphicsPipeline(ctx, desc, cache);
  return w;
}

void CompositePass::setInput(VkImageView hair, VkImageView near, VkImageView nearMask, VkImageView motion) {
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_HAIR, hair, sampler_.handle());
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR, near, sampler_.handle());
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR_MASK, nearMask, sampler_.handle());
  if (!velocity_) return;
  if (motion == VK_NULL_HANDLE) throw Error("CompositePass: a velocity output needs the raster's motion image");
  velocity_->set.writeSampledImage(gpu::COMPOSITE_BINDING_HAIR, hair, sampler_.handle());
  velocity_->set.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR, near, sampler_.handle());
  velocity_->set.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR_MASK, nearMask, sampler_.handle());
  velocity_->set.writeSampledImage(gpu::COMPOSITE_BINDING_MOTION, motion, sampler_.handle());
}

void CompositePass::draw(VkCommandBuffer cmd, VkExtent2D extent) const {
  pipeline_.bind(cmd, set_.set(), extent);
  if (!multisampled_) {
    pipeline_.push(cmd, gpu::COMPOSITE_EVERY_SAMPLE);
    pipeline_.draw(cmd, 3);
  } else {
    for (std::uint32_t samples : {gpu::COMPOSITE_FAR_SAMPLES, gpu::COMPOSITE_NEAR_SAMPLES}) {
      pipeline_.push(cmd, samples);
      pipeline_.draw(cmd, 3);
    }
  }
  if (!velocity_) return;
  velocity_->pipeline.bind(cmd, velocity_->set.set(), extent);
  velocity_->pipeline.push(cmd, velocity_->push);
  velocity_->pipeline.draw(cmd, 3);
}
}  // namespace hp::render
