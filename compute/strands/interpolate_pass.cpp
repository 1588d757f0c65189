#include "compute/strands/interpolate_pass.h"

#include <string>

#include "engine/vk/context.h"

namespace hp::compute {
namespace {
const vk::Binding kInterpolateBindings[] = {
    {gpu::INTERPOLATE_BINDING_GUIDE_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_GUIDE_TANGENTS, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_TRIANGLES, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_BINDINGS, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_TANGENTS, vk::kStorage, vk::kCompute},
    {gpu::INTERPOLATE_BINDING_ATTRIBUTES, vk::kStorage, vk::kCompute},
};

bool perVertexOn(const vk::Context& ctx, InterpolateWalk walk) {
  if (walk == InterpolateWalk::Auto) return ctx.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU;
  return walk == InterpolateWalk::PerVertex;
}

// The staged walk's two blocks of shared memory (interpolate.glsl): 26 KiB, over Vulkan's guaranteed 16.
bool stagingFits(const vk::Context& ctx) {
  const std::uint32_t bytes = 2 * gpu::INTERPOLATE_WORKGROUP_SIZE * gpu::INTERPOLATE_STAGE_ROW * 16;
  return ctx.properties().limits.maxComputeSharedMemorySize >= bytes;
}

// The staged walk is a shader of its own (interpolate_staged.comp), so the other two declare no shared memory.
std::shared_ptr<const vk::ComputePipeline> makeWalk(const vk::Context& ctx, vk::PipelineLibrary* library,
                                                    VkDescriptorSetLayout layout, std::uint32_t walk) {
  if (walk == gpu::INTERPOLATE_WALK_STAGED)
    return vk::makeComputePipeline(ctx, library, "interpolate_staged.comp", gpu::INTERPOLATE_WORKGROUP_SIZE, {layout},
                                   sizeof(gpu::InterpolatePush), "interpolate staged", {});
  return vk::makeComputePipeline(ctx, library, "interpolate.comp", gpu::INTERPOLATE_WORKGROUP_SIZE, {layout},
                                 sizeof(gpu::InterpolatePush),
                                 walk == gpu::INTERPOLATE_WALK_VERTEX ? "interpolate per vertex" : "interpolate", {walk});
}
}  // namespace

const char* interpolateWalkName(InterpolateWalk walk) {
  return walk == InterpolateWalk::Auto ? "auto" : walk == InterpolateWalk::PerVertex ? "vertex" : "strand";
}

std::optional<InterpolateWalk> parseInterpolateWalk(const std::string& name) {
  for (InterpolateWalk w : {InterpolateWalk::Auto, InterpolateWalk::PerStrand, InterpolateWalk::PerVertex})
    if (name == interpolateWalkName(w)) return w;
  return std::nullopt;
}

InterpolatePass::InterpolatePass(const vk::Context& ctx, const StrandBuffers& buffers, vk::PipelineLibrary* library,
                                 const GroomSettings& groom, InterpolateWalk walk)
    : ctx_(&ctx),
      layoutSet_(ctx, kInterpolateBindings, "interpolate layout"),
      perStrand_(makeWalk(ctx, library, layoutSet_.layout(), gpu::INTERPOLATE_WALK_STRAND)) {
  if (perVertexOn(ctx, walk)) {
    perVertex_ = makeWalk(ctx, library, layoutSet_.layout(), gpu::INTERPOLATE_WALK_VERTEX);
    if (stagingFits(ctx)) staged_ = makeWalk(ctx, library, layoutSet_.layout(), gpu::INTERPOLATE_WALK_STAGED);
  }
  setGroom(groom);
  bind(buffers);
}

void InterpolatePass::setGroom(const GroomSettings& groom) {
  groom.validate();
  groom_ = groomParams(groom);
  groomOn_ = groom.any();
  for (Chunk& c : chunks_) c.push.groom = groom_;
}

const vk::ComputePipeline& InterpolatePass::walkPipeline() const {
  if (guidesOnly_) return *perStrand_;
  if (groomOn_) return staged_ ? *staged_ : *perStrand_;
  return perVertex_ ? *perVertex_ : *perStrand_;
}

bool InterpolatePass::walksPerVertex() const { return &walkPipeline() != perStrand_.get(); }

const char* InterpolatePass::walkTaken() const {
  const vk::ComputePipeline* p = &walkPipeline();
  return p == perVertex_.get() ? "vertex" : p == staged_.get() ? "staged" : "strand";
}

void InterpolatePass::bind(const StrandBuffers& buffers) {
  const StrandLayout& l = buffers.layout();
  guidesOnly_ = l.guidesOnly;
  const std::uint32_t mode = l.guidesOnly ? gpu::INTERPOLATE_MODE_GUIDES : gpu::INTERPOLATE_MODE_STRANDS;
  std::vector<Chunk> chunks;
  for (const StrandChunk& c : buffers.chunks()) {
    Chunk chunk{vk::DescriptorSet(*ctx_, kInterpolateBindings, "interpolate [chunk " + std::to_string(chunks.size()) + "]"),
                {c.range.firstStrand, c.range.strandCount, l.verticesPerStrand, mode, groom_}};
    const vk::DescriptorSet& s = chunk.set;
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_GUIDE_POSITIONS, buffers.guidePositions().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_GUIDE_TANGENTS, buffers.guideTangents().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_TRIANGLES, buffers.triangles().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_BINDINGS, c.bindings.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_POSITIONS, c.positions.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_TANGENTS, c.tangents.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_ATTRIBUTES, c.attributes.handle());
    chunks.push_back(std::move(chunk));
  }
  chunks_ = std::move(chunks);
}

void InterpolatePass::record(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "interpolate");
  const vk::ComputePipeline& pipeline = walkPipeline();
  const bool perVertex = &pipeline == perVertex_.get();  // the staged walk has one invocation per strand
  for (const Chunk& c : chunks_) {
    pipeline.bind(cmd, c.set.set());
    pipeline.push(cmd, c.push);
    pipeline.dispatch(cmd, perVertex ? c.push.strandCount * c.push.vertices : c.push.strandCount);
  }
  if (profiler) profiler->end(cmd);
}
}  // namespace hp::compute
