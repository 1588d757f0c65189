#pragma once
// Contract: a per-device cache of pipelines, so many hair instances share one pipeline per shader
// variant instead of building their own (hp::Renderer owns one). A pipeline is keyed by everything that
// makes it different (shaders, specialization constants, push size, formats, samples, blend, depth,
// topology, culling), never by the descriptor set layout handle: every caller of one key builds its sets
// from the same binding table, and identically defined set layouts are compatible (Vulkan spec, "Pipeline
// Layout Compatibility"), so any instance's set binds to the shared pipeline. The first caller's layouts
// create the pipeline; a pipeline layout does not access its set layouts after creation, so that caller
// may go away first. Pipelines are handed out as shared_ptr: a pass keeps what it uses alive even past
// the library. Thread-safe.
//
// The free functions build a pipeline through `library` when there is one, or a private one otherwise
// (passes built alone, as tests and tools do).
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "engine/vk/pipeline.h"

namespace hp::vk {
class PipelineLibrary {
 public:
  explicit PipelineLibrary(const Context& ctx) : ctx_(&ctx) {}
  PipelineLibrary(const PipelineLibrary&) = delete;
  PipelineLibrary& operator=(const PipelineLibrary&) = delete;

  std::shared_ptr<const ComputePipeline> compute(const std::string& shader, std::uint32_t workgroupSize,
                                                 const std::vector<VkDescriptorSetLayout>& sets,
                                                 std::uint32_t pushSize, const std::string& name,
                                                 const std::vector<std::uint32_t>& specialization = {});
  std::shared_ptr<const GraphicsPipeline> graphics(const GraphicsPipelineDesc& desc);
  std::size_t pipelineCount() const;  // distinct pipelines built so far

 private:
  const Context* ctx_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const PipelineBase>> pipelines_;
};

std::shared_ptr<const ComputePipeline> makeComputePipeline(const Context& ctx, PipelineLibrary* library,
                                                           const std::string& shader, std::uint32_t workgroupSize,
                                                           const std::vector<VkDescriptorSetLayout>& sets,
                                                           std::uint32_t pushSize, const std::string& name,
                                                           const std::vector<std::uint32_t>& specialization = {});
std::shared_ptr<const GraphicsPipeline> makeGraphicsPipeline(const Context& ctx, PipelineLibrary* library,
                                                             const GraphicsPipelineDesc& desc);
}  // namespace hp::vk
