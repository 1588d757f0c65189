#pragma once
// The application's own geometry receiving the hair's shadow: a wall behind the heads, drawn by the
// application's pipeline inside its rendering before hairpipe's recordDraw (opaque geometry first: the graphics
// raster blends the hair over what is there), lit by the key light times the
// light the hair lets through (hairpipeHairShadow from the installed <hairpipe/hair_shadows.glsl>, over the
// maps Renderer::hairShadows() hands out). Plain Vulkan through the loader; the shaders are compiled by
// glslc at the sample's build time against the package's include folder (CMakeLists.txt).
#include <vulkan/vulkan.h>

#include <hairpipe/hairpipe.h>

class Backdrop {
 public:
  // shadows: the maps' handles (they live as long as the Renderer); formats: the rendering it draws into (the
  // application's attachments, their depth convention included).
  Backdrop(VkDevice device, const hairpipe::Renderer::HairShadows& shadows, const hairpipe::AttachmentFormats& formats);
  Backdrop(const Backdrop&) = delete;
  Backdrop& operator=(const Backdrop&) = delete;
  ~Backdrop();

  // Inside the rendering, before hairpipe's recordDraw (both set their own viewport). key: the first shadowed
  // light of the frame (shadow slot 0); shadows: this frame's Renderer::hairShadows() (its lookup parameters
  // follow setOpacityTuning); forward: the hair's above the wall. The view's jitter is left out (this
  // application has no TAA).
  void record(VkCommandBuffer cmd, const hairpipe::View& view, const hairpipe::Light& key,
              const hairpipe::Renderer::HairShadows& shadows, const hairpipe::Instance::HairShadowForward& forward) const;

 private:
  VkDevice device_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};
