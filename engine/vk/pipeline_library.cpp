#include "engine/vk/pipeline_library.h"

namespace hp::vk {
namespace {
std::string computeKey(const std::string& shader, std::uint32_t workgroupSize, std::uint32_t pushSize,
                       const std::vector<std::uint32_t>& specialization) {
  std::string key = "c|" + shader + "|" + std::to_string(workgroupSize) + "|" + std::to_string(pushSize);
  for (std::uint32_t s : specialization) key += "|" + std::to_string(s);
  return key;
}

std::string graphicsKey(const GraphicsPipelineDesc& d) {
  std::string key = "g|" + d.vertexShader + "|" + d.fragmentShader + "|" + std::to_string(d.depthFormat) + "|" +
                    std::to_string(d.samples) + "|" + std::to_string(int(d.blend)) + "|" +
                    std::to_string(d.depthTest) + std::to_string(d.depthWrite) + std::to_string(d.alphaToCoverage) +
                    "|" + std::to_string(d.topology) + "|" + std::to_string(d.cullMode) + "|" +
                    std::to_string(d.pushSize) + "|" + std::to_string(d.sets.size());
  for (VkFormat f : d.colorFormats) key += "|" + std::to_string(f);
  return key;
}
}  // namespace

std::shared_ptr<const ComputePipeline> PipelineLibrary::compute(const std::string& shader, std::uint32_t workgroupSize,
                                                                const std::vector<VkDescriptorSetLayout>& sets,
                                                                std::uint32_t pushSize, const std::string& name,
                                                                const std::vector<std::uint32_t>& specialization) {
  const std::string key = computeKey(shader, workgroupSize, pushSize, specialization);
  std::lock_guard lock(mutex_);
  auto found = pipelines_.find(key);
  if (found == pipelines_.end())  // built before it is entered, so a failed build leaves no empty slot
    found = pipelines_.emplace(key, std::make_shared<ComputePipeline>(*ctx_, shader, workgroupSize, sets, pushSize,
                                                                      name, specialization)).first;
  return std::static_pointer_cast<const ComputePipeline>(found->second);
}

std::shared_ptr<const GraphicsPipeline> PipelineLibrary::graphics(const GraphicsPipelineDesc& desc) {
  const std::string key = graphicsKey(desc);
  std::lock_guard lock(mutex_);
  auto found = pipelines_.find(key);
  if (found == pipelines_.end()) found = pipelines_.emplace(key, std::make_shared<GraphicsPipeline>(*ctx_, desc)).first;
  return std::static_pointer_cast<const GraphicsPipeline>(found->second);
}

std::size_t PipelineLibrary::pipelineCount() const {
  std::lock_guard lock(mutex_);
  return pipelines_.size();
}

std::shared_ptr<const ComputePipeline> makeComputePipeline(const Context& ctx, PipelineLibrary* library,
                                                           const std::string& shader, std::uint32_t workgroupSize,
                                                           const std::vector<VkDescriptorSetLayout>& sets,
                                                           std::uint32_t pushSize, const std::string& name,
                                                           const std::vector<std::uint32_t>& specialization) {
  if (library) return library->compute(shader, workgroupSize, sets, pushSize, name, specialization);
  return std::make_shared<ComputePipeline>(ctx, shader, workgroupSize, sets, pushSize, name, specialization);
}

std::shared_ptr<const GraphicsPipeline> makeGraphicsPipeline(const Context& ctx, PipelineLibrary* library,
                                                             const GraphicsPipelineDesc& desc) {
  if (library) return library->graphics(desc);
  return std::make_shared<GraphicsPipeline>(ctx, desc);
}
}  // namespace hp::vk
