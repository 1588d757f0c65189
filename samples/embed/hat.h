#pragma once
// The application's own occluder: a flat cap (a disc) over one of the heads' crown, following its motion. Drawn
// as an engine draws any caster: into hairpipe's heads' depth shadow map after recordShadows (depth only, with
// RendererSettings::applicationOccluders; Renderer::occluderTargets() gives each framed shadow slot's layer and
// light transform, and the barriers are the ones its contract in <hairpipe/renderer.h> lists), so that it
// shadows the hair and the skin below it; and into the application's view, before hairpipe's recordDraw, so
// that it hides the hair behind it. Plain Vulkan through the loader; glslc compiles its shaders.
#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include <hairpipe/hairpipe.h>

class Hat {
 public:
  // shadowFormat: the heads' depth map's (Renderer::OccluderTargets::format, D32_SFLOAT: known before the first
  // frame, checked at each recordShadow); formats: the application's rendering.
  Hat(VkDevice device, VkFormat shadowFormat, const hairpipe::AttachmentFormats& formats);
  Hat(const Hat&) = delete;
  Hat& operator=(const Hat&) = delete;
  ~Hat();

  // After recordShadows, outside any rendering: the cap into every framed slot's layer of the heads' depth map.
  void recordShadow(VkCommandBuffer cmd, const hairpipe::Renderer::OccluderTargets& targets, const glm::mat4& place) const;
  // Inside the application's rendering, before hairpipe's recordDraw.
  void record(VkCommandBuffer cmd, const hairpipe::View& view, const glm::mat4& place) const;

 private:
  void release();
  void draw(VkCommandBuffer cmd, VkPipeline pipeline, const glm::mat4& viewProj, const glm::mat4& place,
            VkExtent2D extent) const;

  VkDevice device_;
  VkFormat shadowFormat_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline shadow_ = VK_NULL_HANDLE;   // depth only, the map's format
  VkPipeline visible_ = VK_NULL_HANDLE;  // the application's attachments
};
