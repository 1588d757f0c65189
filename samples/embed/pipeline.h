#pragma once
// The sample's own Vulkan helpers (main.cpp, backdrop.cpp, hat.cpp): VkResult checks, layout transitions, shader
// modules from glslc's SPIR-V and one graphics pipeline shape (no vertex input, dynamic viewport and scissor,
// depth test with writes). Plain Vulkan through the loader, as the application's engine has it.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include <hairpipe/hairpipe.h>

void check(VkResult result, const char* what);
glm::mat4 toGlm(const hairpipe::Mat4& m);

// One image layout transition of one layer (and its memory dependency) with synchronization2.
void transition(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                VkAccessFlags2 dstAccess, std::uint32_t layer = 0);

// A shader module for as long as the pipelines are being made.
class ShaderModule {
 public:
  ShaderModule(VkDevice device, const std::uint32_t* code, std::size_t bytes);
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
  ~ShaderModule() { vkDestroyShaderModule(device_, module_, nullptr); }
  VkShaderModule get() const { return module_; }

 private:
  VkDevice device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

struct PipelineShape {
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkShaderModule vertex = VK_NULL_HANDLE;
  VkShaderModule fragment = VK_NULL_HANDLE;  // none: depth only
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkFormat color = VK_FORMAT_UNDEFINED;  // none: no colour attachment
  VkFormat depth = VK_FORMAT_UNDEFINED;
  VkFormat stencil = VK_FORMAT_UNDEFINED;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkCullModeFlags cull = VK_CULL_MODE_NONE;  // a closed caster into hairpipe's heads' map: FRONT
  VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
};
// The shape for the application's own rendering (RendererSettings::formats: samples, attachments, depth test).
PipelineShape inRendering(const hairpipe::AttachmentFormats& formats);
VkPipeline makePipeline(VkDevice device, const PipelineShape& shape);
