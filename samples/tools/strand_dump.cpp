#include "samples/tools/strand_dump.h"

#include <algorithm>

#include "engine/vk/barriers.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"

namespace hp::compute {
vk::Buffer uploadGuideParticles(const vk::Context& ctx, const GuideSet& guides, const std::string& name) {
  std::vector<glm::vec4> particles(guides.positions.size());
  for (std::size_t i = 0; i < particles.size(); ++i) particles[i] = glm::vec4(guides.positions[i], 0.0f);
  vk::Buffer buffer(ctx, std::max<VkDeviceSize>(particles.size() * sizeof(glm::vec4), 16),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryKind::DeviceLocal,
                    name);
  vk::upload<glm::vec4>(ctx, buffer, particles, vk::BufferUse::ComputeRead);
  return buffer;
}

void recordStrandPasses(const vk::Context& ctx, VkCommandBuffer cmd, const TessellatePass& tessellate, const InterpolatePass& interpolate,
                        vk::GpuProfiler* profiler) {
  tessellate.record(cmd, profiler);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  interpolate.record(cmd, profiler);
}

HairFileData renderStrandsToHairData(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before,
                                     const std::string& info) {
  const StrandLayout& l = buffers.layout();
  StrandData strands = readRenderStrands(ctx, buffers, before);
  HairFileData hair;
  hair.strandCount = l.strandCount;
  hair.defaultSegments = l.verticesPerStrand - 1;
  hair.setInfoText(info);
  hair.points.reserve(strands.positions.size());
  for (const glm::vec4& p : strands.positions) hair.points.emplace_back(p);
  return hair;
}

StrandRun computeRenderStrands(const vk::Context& ctx, const HairAsset& asset, const StrandOptions& options,
                               const std::string& info, const GroomSettings& groom) {
  const GuideSet& guides = asset.guides;
  StrandBuffers buffers(ctx, guides.guideCount(), guides.particlesPerGuide, asset.topology, options);
  vk::Buffer particles = uploadGuideParticles(ctx, guides);
  TessellatePass tessellate(ctx, particles, buffers);
  InterpolatePass interpolate(ctx, buffers, nullptr, groom);
  vk::GpuProfiler profiler(ctx, 4, "strand passes");
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    profiler.reset(cmd);
    recordStrandPasses(ctx, cmd, tessellate, interpolate, &profiler);
  }, "strand passes");
  StrandRun run{buffers.layout(), renderStrandsToHairData(ctx, buffers, vk::BufferUse::ComputeWrite, info),
                profiler.results()};
  return run;
}
}  // namespace hp::compute
