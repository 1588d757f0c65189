#include "compute/shadows/opacity_pass.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/opacity.h"

namespace hp::render {
namespace {
const vk::Binding kOpacityStrandBindings[] = {
    {gpu::OPACITY_BINDING_POSITIONS, vk::kStorage, vk::kVertex},
    {gpu::OPACITY_BINDING_LIGHT, vk::kStorage, vk::kVertex},
};
const vk::Binding kOpacityHeadBindings[] = {
    {gpu::OPACITY_BINDING_POSITIONS, vk::kStorage, vk::kVertex},
    {gpu::OPACITY_BINDING_INDICES, vk::kStorage, vk::kVertex},
    {gpu::OPACITY_BINDING_LIGHT, vk::kStorage, vk::kVertex},
};
constexpr VkBufferUsageFlags kMeshUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

std::shared_ptr<const vk::GraphicsPipeline> makeOpacityPipeline(const vk::Context& ctx, vk::PipelineLibrary* library,
                                                         VkDescriptorSetLayout layout, VkFormat format, bool head) {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = head ? "opacity_head.vert" : "opacity.vert";
  desc.fragmentShader = "opacity.frag";
  desc.colorFormats.assign(gpu::OPACITY_TARGETS, format);
  desc.blend = vk::BlendMode::Additive;  // order-independent sums, no depth test
  desc.topology = head ? VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST : VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
  desc.sets = {layout};
  desc.pushSize = sizeof(gpu::OpacityPush);
  desc.name = head ? "opacity head" : "opacity strands";
  return vk::makeGraphicsPipeline(ctx, library, desc);
}
}  // namespace

OpacityPass::OpacityPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const HeadMesh& head,
                         const ShadowMaps& maps, vk::PipelineLibrary* library)
    : ctx_(ctx), maps_(maps) {
  uploadHead(head);
  bind(strands);
  strandPipeline_ = makeOpacityPipeline(ctx, library, strandSets_.front().layout(), maps.settings().format, false);
  headPipeline_ = makeOpacityPipeline(ctx, library, headSet_.layout(), maps.settings().format, true);
  vk::GraphicsPipelineDesc depth;
  depth.vertexShader = "head_shadow.vert";
  depth.depthFormat = ShadowMaps::kHeadDepthFormat;
  depth.depthTest = depth.depthWrite = true;
  depth.cullMode = VK_CULL_MODE_FRONT_BIT;  // back faces only: the "second depth" (head_shadow.glsl)
  depth.sets = {headSet_.layout()};
  depth.pushSize = sizeof(glm::mat4);
  depth.name = "head shadow depth";
  headDepthPipeline_ = vk::makeGraphicsPipeline(ctx, library, depth);
  if (const compute::OpacityResolvePass* resolve = maps.resolvePass())
    splat_ = std::make_unique<compute::OpacitySplatPass>(ctx, strands, maps.lightSpace(), resolve->bins(),
                                                         resolve->first(), maps.settings().resolution, resolve->layout(),
                                                         library);
}

HeadSphere OpacityPass::headSphere(const glm::mat4& headToWorld) const {
  if (sphere_.radius <= 0.0f) return {};  // no head, and no application occluders framed for the hair
  const float scale = std::max({glm::length(glm::vec3(headToWorld[0])), glm::length(glm::vec3(headToWorld[1])),
                                glm::length(glm::vec3(headToWorld[2]))});
  return {glm::vec3(headToWorld * glm::vec4(sphere_.centre, 1.0f)), sphere_.radius * scale};
}

void OpacityPass::recordHeadDepth(VkCommandBuffer cmd, const glm::mat4& headToLightClip) const {
  if (headIndexCount_ == 0) return;
  headDepthPipeline_->bind(cmd, headSet_.set(), maps_.headImage().extent());
  headDepthPipeline_->push(cmd, headToLightClip);
  headDepthPipeline_->draw(cmd, headIndexCount_);
}

void OpacityPass::uploadHead(const HeadMesh& head) {
  headIndexCount_ = static_cast<std::uint32_t>(head.indices.size());
  for (std::uint32_t i : head.indices)
    if (i >= head.positions.size()) throw Error("head mesh: index " + std::to_string(i) + " is out of range");
  std::vector<glm::vec4> positions;
  for (const glm::vec3& p : head.positions) positions.emplace_back(p, 1.0f);
  if (headIndexCount_ > 0) sphere_ = boundingSphere(head.positions);  // a head drawn: it frames the heads' depth map
  // Placeholders keep the descriptors valid for a head-less asset (nothing is drawn then).
  if (positions.empty()) positions.emplace_back(0.0f);
  std::vector<std::uint32_t> indices = head.indices;
  if (indices.empty()) indices.push_back(0);
  headPositions_ = vk::Buffer(ctx_, positions.size() * sizeof(glm::vec4), kMeshUsage, vk::MemoryKind::DeviceLocal,
                              "opacity head positions");
  headIndices_ = vk::Buffer(ctx_, indices.size() * sizeof(std::uint32_t), kMeshUsage, vk::MemoryKind::DeviceLocal,
                            "opacity head indices");
  vk::upload<glm::vec4>(ctx_, headPositions_, positions, vk::BufferUse::VertexRead);
  vk::upload<std::uint32_t>(ctx_, headIndices_, indices, vk::BufferUse::VertexRead);
  headSet_ = vk::DescriptorSet(ctx_, kOpacityHeadBindings, "opacity head");
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_POSITIONS, headPositions_.handle());
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_INDICES, headIndices_.handle());
  headSet_.writeStorageBuffer(gpu::OPACITY_BINDING_LIGHT, maps_.lightSpace().handle());
}

void OpacityPass::bind(const compute::StrandBuffers& strands) {
  strands_ = &strands;
  std::vector<vk::DescriptorSet> sets;
  for (const auto& chunk : strands.chunks()) {
    vk::DescriptorSet set(ctx_, kOpacityStrandBindings, "opacity strands [chunk " + std::to_string(sets.size()) + "]");
    set.writeStorageBuffer(gpu::OPACITY_BINDING_POSITIONS, chunk.positions.handle());
    set.writeStorageBuffer(gpu::OPACITY_BINDING_LIGHT, maps_.lightSpace().handle());
    sets.push_back(std::move(set));
  }
  strandSets_ = std::move(sets);
}

namespace {
// The constant per-strand opacity of a level-of-detail prefix: scaled by strands / limit (1 for all).
float prefixOpacity(float strandOpacity, std::uint32_t strands, std::uint32_t limit) {
  const std::uint32_t drawn = std::clamp(limit, 1u, std::max(strands, 1u));
  return drawn >= strands ? strandOpacity : strandOpacity * float(strands) / float(drawn);
}
}  // namespace

void OpacityPass::recordDraws(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& headToWorld,
                              const glm::vec2& strandWidth, std::uint32_t strandLimit) const {
  const VkExtent2D extent = maps_.image().extent();
  const OpacitySettings& settings = maps_.settings();
  const std::uint32_t q = strands_->layout().verticesPerStrand;
  gpu::OpacityPush push{};
  push.opacity =
      settings.footprint ? 1.0f : prefixOpacity(settings.strandOpacity, strands_->layout().strandCount, strandLimit);
  push.verticesPerStrand = q;
  push.slot = slot;
  push.footprint = glm::vec4(strandWidth.x, strandWidth.y, 1.0f / float(settings.resolution),
                             settings.footprint ? 1.0f : 0.0f);
  for (std::size_t c = 0; c < strandSets_.size(); ++c) {
    const std::uint32_t drawn = compute::strandsWithin(strands_->chunks()[c].range, strandLimit);
    if (drawn == 0) break;
    strandPipeline_->bind(cmd, strandSets_[c].set(), extent);
    strandPipeline_->push(cmd, push);
    strandPipeline_->draw(cmd, drawn * (q - 1) * 2);
  }
  recordHeadDraw(cmd, slot, headToWorld);
}

void OpacityPass::recordSplats(VkCommandBuffer cmd, std::uint32_t slot, const glm::vec2& strandWidth,
                               std::uint32_t mode, std::uint32_t strandLimit) const {
  if (!splat_) throw Error("opacity pass: recordSplats needs maps on the compute path");
  const OpacitySettings& settings = maps_.settings();
  const float opacity = prefixOpacity(settings.strandOpacity, strands_->layout().strandCount, strandLimit);
  splat_->record(cmd, {settings.footprint, opacity, strandWidth, slot}, mode, strandLimit);
}

bool OpacityPass::drawsHead() const { return headIndexCount_ > 0 && maps_.settings().headOpacity > 0.0f; }

void OpacityPass::recordHeadDraw(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& headToWorld) const {
  if (!drawsHead()) return;
  gpu::OpacityPush push{};
  push.slot = slot;
  push.headToWorld = headToWorld;
  push.opacity = maps_.settings().headOpacity;
  headPipeline_->bind(cmd, headSet_.set(), maps_.image().extent());
  headPipeline_->push(cmd, push);
  headPipeline_->draw(cmd, headIndexCount_);
}
}  // namespace hp::render
