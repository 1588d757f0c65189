#include "engine/vk/pipeline.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "shaders/embedded_shaders.h"

namespace hp::vk {
namespace {
// A shader module that lives only while its pipeline is created.
struct ScopedModule {
  VkDevice device;
  const VolkDeviceTable* fn_;
  VkShaderModule module = VK_NULL_HANDLE;
  ScopedModule(const Context& ctx, const std::string& shader) : device(ctx.device()), fn_(&ctx.fn()) {
    auto words = shaders::spirv(shader);
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    HP_VK_CHECK(fn_->vkCreateShaderModule(device, &info, nullptr, &module));
    ctx.setName(VK_OBJECT_TYPE_SHADER_MODULE, reinterpret_cast<std::uint64_t>(module), shader);
  }
  ~ScopedModule() { fn_->vkDestroyShaderModule(device, module, nullptr); }
};

VkPipelineShaderStageCreateInfo stageInfo(VkShaderStageFlagBits stage, VkShaderModule module) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = stage;
  info.module = module;
  info.pName = "main";
  return info;
}

VkPipelineColorBlendAttachmentState blendState(BlendMode mode) {
  VkPipelineColorBlendAttachmentState s{};
  s.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                     VK_COLOR_COMPONENT_A_BIT;
  if (mode == BlendMode::None) return s;
  s.blendEnable = VK_TRUE;
  s.colorBlendOp = VK_BLEND_OP_ADD;
  s.alphaBlendOp = VK_BLEND_OP_ADD;
  if (mode == BlendMode::Additive) {
    s.srcColorBlendFactor = s.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
    s.srcAlphaBlendFactor = s.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  } else if (mode == BlendMode::Premultiplied) {
    s.srcColorBlendFactor = s.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    s.dstColorBlendFactor = s.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  } else {
    s.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
    s.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    s.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    s.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  }
  return s;
}
}  // namespace

PipelineBase::~PipelineBase() { release(); }

PipelineBase::PipelineBase(PipelineBase&& other) noexcept { *this = std::move(other); }

PipelineBase& PipelineBase::operator=(PipelineBase&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
    pushStages_ = other.pushStages_;
    bindPoint_ = other.bindPoint_;
  }
  return *this;
}

void PipelineBase::release() {
  if (pipeline_) fn_->vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) fn_->vkDestroyPipelineLayout(device_, layout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
}

void PipelineBase::createLayout(const Context& ctx, const std::vector<VkDescriptorSetLayout>& sets,
                                std::uint32_t pushSize, VkShaderStageFlags pushStages, const std::string& name) {
  device_ = ctx.device();
  fn_ = &ctx.fn();
  pushStages_ = pushStages;
  if (pushSize > ctx.properties().limits.maxPushConstantsSize)
    throw Error("pipeline '" + name + "': push constants of " + std::to_string(pushSize) + " bytes exceed the device limit");
  VkPushConstantRange range{pushStages, 0, pushSize};
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<std::uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  info.pushConstantRangeCount = pushSize ? 1 : 0;
  info.pPushConstantRanges = &range;
  HP_VK_CHECK(fn_->vkCreatePipelineLayout(device_, &info, nullptr, &layout_));
  ctx.setName(VK_OBJECT_TYPE_PIPELINE_LAYOUT, reinterpret_cast<std::uint64_t>(layout_), name + " layout");
}

void PipelineBase::pushConstants(VkCommandBuffer cmd, const void* data, std::uint32_t size) const {
  fn_->vkCmdPushConstants(cmd, layout_, pushStages_, 0, size, data);
}

namespace {
// The VkSpecializationInfo of `values` (constant_id i takes values[i]); null for none. Refers to `values`,
// which must outlive it, and to itself: not copyable.
class Specialization {
 public:
  explicit Specialization(const std::vector<std::uint32_t>& values) {
    for (std::uint32_t i = 0; i < values.size(); ++i)
      entries_.push_back({i, i * std::uint32_t(sizeof(std::uint32_t)), sizeof(std::uint32_t)});
    info_ = {std::uint32_t(entries_.size()), entries_.data(), values.size() * sizeof(std::uint32_t), values.data()};
  }
  Specialization(const Specialization&) = delete;
  Specialization& operator=(const Specialization&) = delete;
  const VkSpecializationInfo* info() const { return entries_.empty() ? nullptr : &info_; }

 private:
  std::vector<VkSpecializationMapEntry> entries_;
  VkSpecializationInfo info_{};
};
}  // namespace

ComputePipeline::ComputePipeline(const Context& ctx, const std::string& shader, std::uint32_t workgroupSize,
                                 const std::vector<VkDescriptorSetLayout>& sets, std::uint32_t pushSize,
                                 const std::string& name, const std::vector<std::uint32_t>& specialization,
                                 VkPipelineCache cache)
    : workgroupSize_(workgroupSize), maxGroupsX_(ctx.properties().limits.maxComputeWorkGroupCount[0]) {
  if (workgroupSize == 0 || workgroupSize > ctx.properties().limits.maxComputeWorkGroupInvocations)
    throw Error("pipeline '" + name + "': workgroup size " + std::to_string(workgroupSize) + " is not supported");
  bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  createLayout(ctx, sets, pushSize, VK_SHADER_STAGE_COMPUTE_BIT, name);
  ScopedModule module(ctx, shader);
  const Specialization spec(specialization);
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = stageInfo(VK_SHADER_STAGE_COMPUTE_BIT, module.module);
  info.stage.pSpecializationInfo = spec.info();
  info.layout = layout_;
  HP_VK_CHECK(fn_->vkCreateComputePipelines(device_, cache, 1, &info, nullptr, &pipeline_));
  ctx.setName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(pipeline_), name);
}

void ComputePipeline::bind(VkCommandBuffer cmd, VkDescriptorSet set) const {
  fn_->vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  if (set) fn_->vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set, 0, nullptr);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, std::uint32_t threads) const {
  if (threads == 0) return;
  const std::uint32_t groups = (threads + workgroupSize_ - 1) / workgroupSize_;
  const std::uint32_t x = std::min(groups, maxGroupsX_);
  const std::uint32_t y = (groups + x - 1) / x;
  fn_->vkCmdDispatch(cmd, x, y, 1);
}

void ComputePipeline::dispatchIndirect(VkCommandBuffer cmd, VkBuffer args, VkDeviceSize offset) const {
  fn_->vkCmdDispatchIndirect(cmd, args, offset);
}

GraphicsPipeline::GraphicsPipeline(const Context& ctx, const GraphicsPipelineDesc& d, VkPipelineCache cache) {
  bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
  createLayout(ctx, d.sets, d.pushSize, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, d.name);
  ScopedModule vs(ctx, d.vertexShader);
  std::vector<VkPipelineShaderStageCreateInfo> stages{stageInfo(VK_SHADER_STAGE_VERTEX_BIT, vs.module)};
  std::optional<ScopedModule> fs;
  const Specialization fragmentSpec(d.fragmentSpecialization);
  if (!d.fragmentShader.empty()) {
    fs.emplace(ctx, d.fragmentShader);
    stages.push_back(stageInfo(VK_SHADER_STAGE_FRAGMENT_BIT, fs->module));
    stages.back().pSpecializationInfo = fragmentSpec.info();
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = d.topology;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = d.cullMode;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = d.samples;
  multisample.alphaToCoverageEnable = d.alphaToCoverage ? VK_TRUE : VK_FALSE;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = d.depthTest ? VK_TRUE : VK_FALSE;
  depth.depthWriteEnable = d.depthWrite ? VK_TRUE : VK_FALSE;
  depth.depthCompareOp = d.depthCompare;
  VkPipelineColorBlendAttachmentState written = blendState(d.blend);
  written.colorWriteMask = d.writtenComponents;
  std::vector<VkPipelineColorBlendAttachmentState> blends(d.colorFormats.size(), written);
  for (std::size_t i = 0; i < blends.size(); ++i)
    if (i >= 32 || (d.writtenColors >> i & 1u) == 0) blends[i] = VkPipelineColorBlendAttachmentState{};
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = static_cast<std::uint32_t>(blends.size());
  blend.pAttachments = blends.data();
  VkDynamicState dynamicStates[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamicStates;
  VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
  rendering.colorAttachmentCount = static_cast<std::uint32_t>(d.colorFormats.size());
  rendering.pColorAttachmentFormats = d.colorFormats.data();
  rendering.depthAttachmentFormat = d.depthFormat;
  rendering.stencilAttachmentFormat = d.stencilFormat;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.layout = layout_;
  HP_VK_CHECK(fn_->vkCreateGraphicsPipelines(device_, cache, 1, &info, nullptr, &pipeline_));
  ctx.setName(VK_OBJECT_TYPE_PIPELINE, reinterpret_cast<std::uint64_t>(pipeline_), d.name);
}

void GraphicsPipeline::bind(VkCommandBuffer cmd, VkDescriptorSet set, VkExtent2D extent,
                            std::optional<std::uint32_t> dynamicOffset) const {
  fn_->vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  if (set)
    fn_->vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set, dynamicOffset ? 1 : 0,
                            dynamicOffset ? &*dynamicOffset : nullptr);
  // Flip Y so that +Y is up in clip space, as in GL-style projection matrices from glm.
  VkViewport vp{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, extent};
  fn_->vkCmdSetViewport(cmd, 0, 1, &vp);
  fn_->vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void GraphicsPipeline::draw(VkCommandBuffer cmd, std::uint32_t vertexCount) const {
  fn_->vkCmdDraw(cmd, vertexCount, 1, 0, 0);
}
}  // namespace hp::vk
