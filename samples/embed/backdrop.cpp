#include "backdrop.h"

#include <cstdint>

#include <glm/glm.hpp>

#include "pipeline.h"

namespace {
// SPIR-V from glslc -mfmt=c (CMakeLists.txt).
const std::uint32_t kVertexCode[] =
#include "backdrop.vert.inc"
    ;
const std::uint32_t kFragmentCode[] =
#include "backdrop.frag.inc"
    ;

struct Push {  // backdrop.vert / .frag
  glm::mat4 viewProj;
  glm::vec4 lightDirection, lightColor, hairParams, hairForward;
};
static_assert(sizeof(Push) == 128);
}  // namespace

Backdrop::Backdrop(VkDevice device, const hairpipe::Renderer::HairShadows& shadows,
                   const hairpipe::AttachmentFormats& formats)
    : device_(device) {
  const VkDescriptorSetLayoutBinding bindings[] = {
      {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo li{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  li.bindingCount = 2;
  li.pBindings = bindings;
  check(vkCreateDescriptorSetLayout(device, &li, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");
  const VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
  VkDescriptorPoolCreateInfo pi{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pi.maxSets = 1;
  pi.poolSizeCount = 2;
  pi.pPoolSizes = sizes;
  check(vkCreateDescriptorPool(device, &pi, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo ai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  ai.descriptorPool = pool_;
  ai.descriptorSetCount = 1;
  ai.pSetLayouts = &setLayout_;
  check(vkAllocateDescriptorSets(device, &ai, &set_), "vkAllocateDescriptorSets");
  // hairpipe's maps and light framing, bound as they are handed out (the layout hairShadows() names).
  const VkDescriptorImageInfo maps{shadows.sampler, shadows.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  const VkDescriptorBufferInfo lights{shadows.lightSpaces, 0, shadows.lightSpacesBytes};
  VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
  writes[0].dstSet = writes[1].dstSet = set_;
  writes[0].dstBinding = 0;
  writes[0].descriptorCount = 1;
  writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  writes[0].pImageInfo = &maps;
  writes[1].dstBinding = 1;
  writes[1].descriptorCount = 1;
  writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  writes[1].pBufferInfo = &lights;
  vkUpdateDescriptorSets(device, 2, writes, 0, nullptr);

  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &setLayout_;
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  check(vkCreatePipelineLayout(device, &pli, nullptr, &layout_), "vkCreatePipelineLayout");

  const ShaderModule vertex(device, kVertexCode, sizeof(kVertexCode));
  const ShaderModule fragment(device, kFragmentCode, sizeof(kFragmentCode));
  PipelineShape shape = inRendering(formats);
  shape.layout = layout_;
  shape.vertex = vertex.get();
  shape.fragment = fragment.get();
  shape.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  pipeline_ = makePipeline(device, shape);
}

Backdrop::~Backdrop() {
  vkDestroyPipeline(device_, pipeline_, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
  vkDestroyDescriptorPool(device_, pool_, nullptr);
  vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
}

void Backdrop::record(VkCommandBuffer cmd, const hairpipe::View& view, const hairpipe::Light& key,
                      const hairpipe::Renderer::HairShadows& shadows,
                      const hairpipe::Instance::HairShadowForward& forward) const {
  Push push;
  push.viewProj = toGlm(view.projection) * toGlm(view.view);
  push.lightDirection = glm::vec4(key.direction.x, key.direction.y, key.direction.z, 0.0f);
  push.lightColor = glm::vec4(key.color.x, key.color.y, key.color.z, 1.0f) * key.intensity;
  push.hairParams = glm::vec4(shadows.opacityScale, shadows.bias, shadows.deep ? 1.0f : 0.0f, 0.0f);
  push.hairForward = glm::vec4(forward.albedo.x, forward.albedo.y, forward.albedo.z, forward.weight);
  // The viewport hairpipe sets for the same view: the whole extent, y up (a negative height).
  const VkViewport viewport{0.0f, float(view.extent.height), float(view.extent.width), -float(view.extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, view.extent};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push), &push);
  vkCmdDraw(cmd, 4, 1, 0, 0);
}
