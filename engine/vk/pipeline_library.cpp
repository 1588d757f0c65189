#include "engine/vk/pipeline_library.h"

#include <cstring>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

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
                    std::to_string(d.stencilFormat) + "|" + std::to_string(d.depthCompare) + "|" +
                    std::to_string(d.samples) + "|" + std::to_string(int(d.blend)) + "|" +
                    std::to_string(d.depthTest) + std::to_string(d.depthWrite) + std::to_string(d.alphaToCoverage) +
                    "|" + std::to_string(d.topology) + "|" + std::to_string(d.cullMode) + "|" +
                    std::to_string(d.pushSize) + "|" + std::to_string(d.sets.size()) + "|w" +
                    std::to_string(d.writtenColors) + "c" + std::to_string(d.writtenComponents);
  for (VkFormat f : d.colorFormats) key += "|" + std::to_string(f);
  key += "|s";
  for (std::uint32_t s : d.fragmentSpecialization) key += "|" + std::to_string(s);
  return key;
}
std::uint32_t readU32(std::span<const std::uint8_t> data, std::size_t offset) {
  std::uint32_t v = 0;
  std::memcpy(&v, data.data() + offset, sizeof(v));
  return v;
}
}  // namespace

bool PipelineLibrary::cacheMatchesDevice(const Context& ctx, std::span<const std::uint8_t> data) {
  constexpr std::size_t kHeader = 16 + VK_UUID_SIZE;  // VkPipelineCacheHeaderVersionOne
  if (data.size() < kHeader)
    throw Error("pipeline cache data of " + std::to_string(data.size()) + " bytes is shorter than its " +
                std::to_string(kHeader) + "-byte header");
  const std::uint32_t headerSize = readU32(data, 0);
  if (headerSize < kHeader || headerSize > data.size())
    throw Error("pipeline cache data: its header says " + std::to_string(headerSize) + " bytes, of " +
                std::to_string(data.size()));
  const VkPhysicalDeviceProperties& p = ctx.properties();
  return readU32(data, 4) == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && readU32(data, 8) == p.vendorID &&
         readU32(data, 12) == p.deviceID && std::memcmp(data.data() + 16, p.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

PipelineLibrary::PipelineLibrary(const Context& ctx, std::span<const std::uint8_t> initialCache) : ctx_(&ctx) {
  VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  if (!initialCache.empty() && cacheMatchesDevice(ctx, initialCache)) {
    info.initialDataSize = initialCache.size();
    info.pInitialData = initialCache.data();
  }
  HP_VK_CHECK(ctx.fn().vkCreatePipelineCache(ctx.device(), &info, nullptr, &cache_));
  ctx.setName(VK_OBJECT_TYPE_PIPELINE_CACHE, reinterpret_cast<std::uint64_t>(cache_), "hairpipe pipeline cache");
}

PipelineLibrary::~PipelineLibrary() { ctx_->fn().vkDestroyPipelineCache(ctx_->device(), cache_, nullptr); }

std::vector<std::uint8_t> PipelineLibrary::cacheData() const {
  std::lock_guard lock(mutex_);
  std::size_t size = 0;
  HP_VK_CHECK(ctx_->fn().vkGetPipelineCacheData(ctx_->device(), cache_, &size, nullptr));
  std::vector<std::uint8_t> data(size);
  HP_VK_CHECK(ctx_->fn().vkGetPipelineCacheData(ctx_->device(), cache_, &size, data.data()));
  data.resize(size);
  return data;
}

std::shared_ptr<const ComputePipeline> PipelineLibrary::compute(const std::string& shader, std::uint32_t workgroupSize,
                                                                const std::vector<VkDescriptorSetLayout>& sets,
                                                                std::uint32_t pushSize, const std::string& name,
                                                                const std::vector<std::uint32_t>& specialization) {
  const std::string key = computeKey(shader, workgroupSize, pushSize, specialization);
  std::lock_guard lock(mutex_);
  auto found = pipelines_.find(key);
  if (found == pipelines_.end())  // built before it is entered, so a failed build leaves no empty slot
    found = pipelines_.emplace(key, std::make_shared<ComputePipeline>(*ctx_, shader, workgroupSize, sets, pushSize,
                                                                      name, specialization, cache_)).first;
  return std::static_pointer_cast<const ComputePipeline>(found->second);
}

std::shared_ptr<const GraphicsPipeline> PipelineLibrary::graphics(const GraphicsPipelineDesc& desc) {
  const std::string key = graphicsKey(desc);
  std::lock_guard lock(mutex_);
  auto found = pipelines_.find(key);
  if (found == pipelines_.end())
    found = pipelines_.emplace(key, std::make_shared<GraphicsPipeline>(*ctx_, desc, cache_)).first;
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
