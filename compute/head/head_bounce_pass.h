#pragma once
// Contract: draws one instance's head into the head bounce map (HeadBounceMap, shaders/head_bounce.vert/.frag)
// from the light: the head mesh buffers of its HeadPass, a frame block of the instance's (a storage buffer
// holding a RenderFrame: light, skin and hair colours, opacity settings, the map's framing
// headShadowViewProj; Renderer::recordShadows writes it) and the shadows' opacity maps and LightSpace.
// draw() goes between HeadBounceMap::begin and end. Owns its descriptor set; the pipeline is the library's.
#include <glm/glm.hpp>

#include <memory>

#include "compute/head/head_pass.h"
#include "compute/shadows/shadow_inputs.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/pipeline_library.h"

namespace hp::render {
class HeadBouncePass {
 public:
  HeadBouncePass(const vk::Context& ctx, const HeadPass& head, VkBuffer frameBlock, const ShadowInputs& shadows,
                 vk::PipelineLibrary* library = nullptr);
  void draw(VkCommandBuffer cmd, const glm::mat4& headToWorld) const;

 private:
  const HeadPass* head_;
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::GraphicsPipeline> pipeline_;
};
}  // namespace hp::render
