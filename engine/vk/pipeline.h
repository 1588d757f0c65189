#pragma once
// Contract: compute and graphics pipelines built from embedded SPIR-V (shaders/embedded_shaders.h),
// move-only, each with its own layout. Graphics pipelines use dynamic rendering (no render passes) and
// vertex pulling (no vertex input state); viewport and scissor are dynamic.
// ComputePipeline knows its workgroup size (from the shared GLSL/C++ header), so dispatch() takes a
// thread count and never a restated literal.
#include "hairpipe_volk.h"

#include <cstdint>

#include <optional>
#include <string>
#include <vector>

namespace hp::vk {
class Context;

class PipelineBase {
 public:
  PipelineBase() = default;
  ~PipelineBase();
  PipelineBase(PipelineBase&& other) noexcept;
  PipelineBase& operator=(PipelineBase&& other) noexcept;
  PipelineBase(const PipelineBase&) = delete;
  PipelineBase& operator=(const PipelineBase&) = delete;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  void pushConstants(VkCommandBuffer cmd, const void* data, std::uint32_t size) const;
  template <class T>
  void push(VkCommandBuffer cmd, const T& constants) const {
    pushConstants(cmd, &constants, sizeof(T));
  }

 protected:
  void createLayout(const Context& ctx, const std::vector<VkDescriptorSetLayout>& sets, std::uint32_t pushSize,
                    VkShaderStageFlags pushStages, const std::string& name);
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkShaderStageFlags pushStages_ = 0;
  VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
};

class ComputePipeline : public PipelineBase {
 public:
  ComputePipeline() = default;
  // `specialization[i]` is the value of the shader's `layout(constant_id = i) const uint` (i from 0).
  // `cache`: a VkPipelineCache the creation reads and fills (PipelineLibrary's), or none.
  ComputePipeline(const Context& ctx, const std::string& shader, std::uint32_t workgroupSize,
                  const std::vector<VkDescriptorSetLayout>& sets, std::uint32_t pushSize, const std::string& name,
                  const std::vector<std::uint32_t>& specialization = {}, VkPipelineCache cache = VK_NULL_HANDLE);
  void bind(VkCommandBuffer cmd, VkDescriptorSet set) const;
  // Enough workgroups for `threads` invocations. Past maxComputeWorkGroupCount[0] groups the grid
  // becomes 2D; shaders use hpThreadId(size) from shaders/common.glsl and bounds-check against their count.
  void dispatch(VkCommandBuffer cmd, std::uint32_t threads) const;
  // Groups from a VkDispatchIndirectCommand the device wrote at `offset` (in BufferUse::IndirectRead).
  void dispatchIndirect(VkCommandBuffer cmd, VkBuffer args, VkDeviceSize offset) const;
  std::uint32_t workgroupSize() const { return workgroupSize_; }

 private:
  std::uint32_t workgroupSize_ = 0;
  std::uint32_t maxGroupsX_ = 65535;
};

// Premultiplied: src + (1 - src.a) dst (a compositor's "over" for premultiplied colour).
enum class BlendMode { None, Alpha, Additive, Premultiplied };

struct GraphicsPipelineDesc {
  std::string vertexShader;    // embedded shader names, e.g. "strands.vert"
  std::string fragmentShader;
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkFormat stencilFormat = VK_FORMAT_UNDEFINED;  // the rendering's stencil attachment (none: UNDEFINED)
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;  // with depthTest
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  BlendMode blend = BlendMode::None;  // applied to the written colour attachments
  // Bit i set: colour attachment i is written (with `blend`); the others keep what they hold (write mask 0;
  // where attachments differ so, the independentBlend feature is needed).
  std::uint32_t writtenColors = ~0u;
  // The channels the written attachments take (the rest keep theirs).
  VkColorComponentFlags writtenComponents = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                            VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  bool depthTest = false;
  bool depthWrite = false;
  bool alphaToCoverage = false;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
  std::vector<VkDescriptorSetLayout> sets;
  std::uint32_t pushSize = 0;
  std::string name;
  // `fragmentSpecialization[i]`: the fragment shader's `layout(constant_id = i) const uint` (i from 0).
  std::vector<std::uint32_t> fragmentSpecialization;
};

class GraphicsPipeline : public PipelineBase {
 public:
  GraphicsPipeline() = default;
  GraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& desc, VkPipelineCache cache = VK_NULL_HANDLE);
  // `dynamicOffset`: the offset of the set's one dynamic storage buffer, if its layout has one.
  void bind(VkCommandBuffer cmd, VkDescriptorSet set, VkExtent2D extent,
            std::optional<std::uint32_t> dynamicOffset = std::nullopt) const;
  // One non-indexed, non-instanced draw of `vertexCount` vertices (vertex pulling) after bind().
  void draw(VkCommandBuffer cmd, std::uint32_t vertexCount) const;
};
}  // namespace hp::vk
