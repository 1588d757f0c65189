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
// The library also holds a VkPipelineCache every pipeline it builds goes through: started from an
// application's earlier cacheData() (data from another device, driver or cache version is ignored, as
// drivers do; data too short to hold the cache header, or whose header says so, is refused with
// hp::Error), and read back with cacheData().
//
// The free functions build a pipeline through `library` when there is one, or a private one otherwise
// (passes built alone, as tests and tools do).
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "engine/vk/pipeline.h"

namespace hp::vk {
class PipelineLibrary {
 public:
  explicit PipelineLibrary(const Context& ctx, std::span<const std::uint8_t> initialCache = {});
  ~PipelineLibrary();
  PipelineLibrary(const PipelineLibrary&) = delete;
  PipelineLibrary& operator=(const PipelineLibrary&) = delete;
  // The pipeline cache's data now (vkGetPipelineCacheData), to start a later run's library with.
  std::vector<std::uint8_t> cacheData() const;
  // For passes that own their pipelines instead of sharing the library's (the compute raster target).
  VkPipelineCache cache() const { return cache_; }
  // Whether `data` is a pipeline cache of this device and driver (header version one, vendor and device
  // IDs, pipelineCacheUUID); throws hp::Error naming the problem when it is too short to be one.
  static bool cacheMatchesDevice(const Context& ctx, std::span<const std::uint8_t> data);

  std::shared_ptr<const ComputePipeline> compute(const std::string& shader, std::uint32_t workgroupSize,
                                                 const std::vector<VkDescriptorSetLayout>& sets,
                                                 std::uint32_t pushSize, const std::string& name,
                                                 const std::vector<std::uint32_t>& specialization = {});
  std::shared_ptr<const GraphicsPipeline> graphics(const GraphicsPipelineDesc& desc);
  std::size_t pipelineCount() const;  // distinct pipelines built so far

 private:
  const Context* ctx_;
  VkPipelineCache cache_ = VK_NULL_HANDLE;
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
