#include "hat.h"

#include <cstdint>
#include <stdexcept>

#include "pipeline.h"

namespace {
// SPIR-V from glslc -mfmt=c (CMakeLists.txt).
const std::uint32_t kVertexCode[] =
#include "hat.vert.inc"
    ;
const std::uint32_t kFragmentCode[] =
#include "hat.frag.inc"
    ;

struct Push {  // hat.vert / .frag (within the 128 bytes every device has)
  glm::mat4 transform;
  glm::vec4 disc, color;
};
static_assert(sizeof(Push) == 96);

constexpr std::uint32_t kSegments = 32;
// Radius, height above the head's origin (the default head's hair is about that high at the crown), segments (m).
const glm::vec4 kDisc{0.15f, 0.115f, float(kSegments), 0.0f};
}  // namespace

Hat::Hat(VkDevice device, VkFormat shadowFormat, const hairpipe::AttachmentFormats& formats)
    : device_(device), shadowFormat_(shadowFormat) {
  const VkPushConstantRange push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push)};
  VkPipelineLayoutCreateInfo pli{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  pli.pushConstantRangeCount = 1;
  pli.pPushConstantRanges = &push;
  check(vkCreatePipelineLayout(device, &pli, nullptr, &layout_), "vkCreatePipelineLayout");
  const ShaderModule vertex(device, kVertexCode, sizeof(kVertexCode));
  const ShaderModule fragment(device, kFragmentCode, sizeof(kFragmentCode));
  // The map: depth only, LESS_OR_EQUAL (its convention, whatever the application's). A disc has no back face of
  // its own, so neither side is culled (the contract's front-face culling is for closed meshes).
  PipelineShape map;
  map.layout = layout_;
  map.vertex = vertex.get();
  map.depth = shadowFormat;
  PipelineShape view = inRendering(formats);
  view.layout = layout_;
  view.vertex = vertex.get();
  view.fragment = fragment.get();
  try {
    shadow_ = makePipeline(device, map);
    visible_ = makePipeline(device, view);
  } catch (...) {
    release();  // what was made so far
    throw;
  }
}

Hat::~Hat() { release(); }

void Hat::release() {  // null handles are ignored
  vkDestroyPipeline(device_, visible_, nullptr);
  vkDestroyPipeline(device_, shadow_, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
}

void Hat::draw(VkCommandBuffer cmd, VkPipeline pipeline, const glm::mat4& viewProj, const glm::mat4& place,
               VkExtent2D extent) const {
  const Push push{viewProj * place, kDisc, glm::vec4(0.16f, 0.12f, 0.09f, 1.0f)};
  // hairpipe's convention for both: the whole extent, y up (a negative height).
  const VkViewport viewport{0.0f, float(extent.height), float(extent.width), -float(extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(Push), &push);
  vkCmdDraw(cmd, 3 * kSegments, 1, 0, 0);
}

void Hat::recordShadow(VkCommandBuffer cmd, const hairpipe::Renderer::OccluderTargets& targets,
                       const glm::mat4& place) const {
  constexpr VkPipelineStageFlags2 kTests =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  constexpr VkAccessFlags2 kDepth = VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  if (targets.format != shadowFormat_) throw std::runtime_error("hat: the heads' depth map is not in the pipeline's format");
  for (std::uint32_t slot = 0; slot < targets.slots; ++slot) {
    if (!targets.framed[slot]) continue;
    // DEPTH_STENCIL_ATTACHMENT_OPTIMAL: DEPTH_ATTACHMENT_OPTIMAL would need separateDepthStencilLayouts.
    transition(cmd, targets.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
               VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, kTests, kDepth, slot);
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = targets.layers[slot];
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // hairpipe's heads are already in it
    depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
    ri.renderArea = {{0, 0}, targets.extent};
    ri.layerCount = 1;
    ri.pDepthAttachment = &depth;
    vkCmdBeginRendering(cmd, &ri);
    draw(cmd, shadow_, toGlm(targets.viewProjection[slot]), place, targets.extent);
    vkCmdEndRendering(cmd);
    transition(cmd, targets.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
               VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
               VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, slot);
  }
}

void Hat::record(VkCommandBuffer cmd, const hairpipe::View& view, const glm::mat4& place) const {
  draw(cmd, visible_, toGlm(view.projection) * toGlm(view.view), place, view.extent);
}
