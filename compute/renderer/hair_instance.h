#pragma once
// Contract: one head of hair drawn by a Renderer: its simulation state (guide particles), strand buffers,
// descriptor sets, per-head parameters and its ring of per-frame constants. Pipelines, LUT textures and
// shadow maps are the Renderer's, shared with every other instance. Created by Renderer::createInstance;
// the Renderer outlives its instances.
//
// Per frame, before the Renderer's record calls: setMotion() (where the head is; the draws and shadows of
// that frame use motion.to). Setters validate their input and throw hp::Error; they are host-only and may
// be called between frames while earlier frames are still in flight: what the GPU may still read is
// retired through the Renderer and destroyed once those frames are done (no device idle).
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compute/shadows/bounds_pass.h"
#include "compute/strands/interpolate_pass.h"
#include "compute/strands/simulate_pass.h"
#include "compute/strands/strand_buffers.h"
#include "compute/strands/tessellate_pass.h"
#include "engine/core/hair/hair_asset.h"
#include "compute/head/head_bounce_pass.h"
#include "compute/head/head_pass.h"
#include "compute/head/strand_bounce_pass.h"
#include "compute/renderer/lut_build.h"
#include "compute/raster/marschner_textures.h"
#include "compute/shadows/opacity_pass.h"
#include "compute/raster/strand_pass.h"
#include "compute/renderer/renderer_settings.h"
#include "engine/vk/buffer.h"

namespace hp {
class Renderer;

class HairInstance {
 public:
  ~HairInstance();
  HairInstance(const HairInstance&) = delete;
  HairInstance& operator=(const HairInstance&) = delete;

  // This frame's head motion (from -> to); throws hp::Error on non-finite matrices.
  void setMotion(const HeadMotion& motion);
  // Where the head is drawn and casts its shadow when it is not simulated this frame.
  void setHeadToWorld(const glm::mat4& headToWorld);
  // Colliders for the next frames (head space, moving with the motion's head pair); scalp input Bones:
  // the bone matrices at the end of the next frame. Both any time between frames.
  void setColliders(std::span<const SphereCollider> spheres, std::span<const CapsuleCollider> capsules = {}) {
    simulate_.setColliders(spheres, capsules);
  }
  void setBones(std::span<const glm::mat4> bones) { simulate_.setBones(bones); }
  // Scalp input RootFrames: the application's buffer the next recorded frames read (the descriptor set the
  // frames in flight bind is retired, not rewritten).
  void setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes);
  // A skinned character's pose for the next frame (SimulatePass::setCharacterPose): the collision grid is
  // rebuilt from it and the drawn head (the character) takes it.
  void setCharacterPose(std::span<const glm::mat4> bones) { simulate_.setCharacterPose(bones); }
  // Before the first frame, or for tables the Renderer has cached: applied at once (uploads batched as
  // withUploads says). Otherwise the tables are built on a worker thread and the instance draws its current
  // material until a recordUpdate or recordShadows finds them done (materialPending()); a later
  // setMaterial replaces a pending one.
  void setMaterial(const HairMaterial& material, LutMode mode);
  bool materialPending() const { return pending_ != nullptr; }
  // Blocks until a pending material's tables are built (not applied: the next recordUpdate or recordShadows
  // does that). For tools and tests that need a change in a known frame; waits on the CPU worker only.
  void waitForMaterial() const {
    if (pending_) pending_->wait();
  }
  // Why the last material change made in the frame loop did not apply (its tables' build or upload failed;
  // empty: it applied, is pending, or none was made). A later setMaterial clears it.
  const std::string& materialError() const { return materialError_; }
  void setLook(const render::LookSettings& look);
  void setLod(const hairpipe::LodSettings& lod);
  void setSimulation(const SimulationParams& params);
  // Clumps, curl and frizz from the next recordUpdate on (no buffers change).
  void setGroom(const GroomSettings& groom);
  // A new interpolation topology (density) or strand options: new strand buffers, filled by the next update.
  void setStrands(const InterpolationTopology& topology, const compute::StrandOptions& options);

  const InstanceSettings& settings() const { return settings_; }
  const glm::mat4& headToWorld() const { return motion_.to; }
  const compute::StrandBuffers& strands() const { return geometry_->buffers; }
  // A recordUpdate has computed the strands' positions (false after construction and setStrands until then:
  // the Renderer refuses to draw them before).
  bool strandsComputed() const { return geometry_->computed; }
  const render::MarschnerTextures& marschner() const { return *marschner_; }
  // What its hair passes on forward to a diffuse receiver beneath it (render::hairForward): the material and
  // look in effect.
  glm::vec4 shadowForward() const;
  // The instance's frame block for a view or pass: its material and its tables' forward albedo, `look`.
  gpu::RenderFrame frameBlock(const CameraMatrices& camera, VkExtent2D extent, const render::FrameLights& lights,
                              const render::LookSettings& look) const;
  const SimulatePass& simulation() const { return simulate_; }
  // Level of detail: what a view with its eye at `eye` draws (fraction of the strands, their count), and
  // what the shadows draw (the largest fraction of the views most recently drawn; 1 before any).
  float lodFraction(const glm::vec3& eye) const;
  std::uint32_t lodStrands(float fraction) const;
  float shadowLodFraction() const { return viewsDrawn_ ? largestViewFraction_ : 1.0f; }
  // Tools (scripted settling frames outside a frame loop) drive the simulation directly.
  SimulatePass& simulationForTools() { return simulate_; }

 private:
  friend class Renderer;
  // Everything sized by the strand topology and options, rebuilt (and retired) together.
  struct Geometry {
    compute::StrandBuffers buffers;
    compute::TessellatePass tessellate;
    compute::InterpolatePass interpolate;
    compute::BoundsPass bounds;
    render::OpacityPass opacity;
    render::StrandBouncePass bounce;  // the skin's bounce along the strands, read by both rasters' shading
    bool previousKept = false;  // the buffers' previous positions hold a frame (recordUpdate copied them once)
    bool computed = false;      // a recordUpdate has written the positions (undefined in new buffers until then)
    // occluders: the heads' depth map's framing for the application's occluders (none: radius 0).
    Geometry(Renderer& r, const SimulatePass& sim, const InterpolationTopology& topology, const HeadMesh& head,
             const render::HeadSphere& occluders, const InstanceSettings& s, const vk::Buffer& bounceFrame);
  };

  HairInstance(Renderer& renderer, const HairAsset& asset, const InstanceSettings& settings,
               const glm::mat4& initialHead);
  std::shared_ptr<render::StrandPass> makeStrandPass(const Geometry& geometry,
                                                    const render::MarschnerTextures& marschner) const;
  void replaceStrandPass(std::shared_ptr<render::StrandPass> pass);
  std::uint32_t frameOffset(std::uint64_t frame, std::uint32_t view) const;
  gpu::RenderFrame* frameSlot(std::uint64_t frame, std::uint32_t view) const;
  // The textures `make` returns in use from now on (the old ones retired), for `material` in `mode`. `make`
  // runs inside the change's upload batch: in the frame loop its uploads go into the next frame's commands.
  using TexturesMaker = std::function<std::shared_ptr<render::MarschnerTextures>()>;
  void applyMaterial(const TexturesMaker& make, const HairMaterial& material, LutMode mode);
  // After a frame's update that posed the character: its posed vertices into the head draws' buffers.
  void recordCharacterCopies(const vk::Context& ctx, VkCommandBuffer cmd) const;
  // A worker's tables, once done: uploaded and applied (Renderer::applyReadyMaterials).
  void applyReadyMaterial();
  // A view of `frame` draws `fraction` (the shadows of the next frame use the largest of a frame's).
  void noteViewFraction(std::uint64_t frame, float fraction);
  // recordDraw's frame block for view slot `index` of `frame`, checked before anything is written: the draws
  // of one frame read the block as it was written last (host memory), so a second view with the same index
  // and another block (another camera, extent or jitter) would draw the first with its camera. Throws
  // hp::Error naming the index; the same block again passes.
  void checkFrameBlock(std::uint64_t frame, std::uint32_t index, const gpu::RenderFrame& block) const;
  // Writes it (after every instance's check).
  void writeFrameBlock(std::uint64_t frame, std::uint32_t index, const gpu::RenderFrame& block);

  Renderer& renderer_;
  InstanceSettings settings_;
  HeadMesh headMesh_;  // the asset's head (none when !drawHead); kept for rebuilding the opacity pass with new strands
  render::HeadSphere occluderSphere_;  // RendererSettings::applicationOccluders without a head: the guides' sphere
  HeadMotion motion_;
  SimulatePass simulate_;
  // The frame block the head bounce map's draw and the bounce along the strands read (light, colours, opacity
  // settings, the map's framing), written by Renderer::recordShadows with vkCmdUpdateBuffer.
  vk::Buffer bounceFrame_;
  std::shared_ptr<Geometry> geometry_;
  std::shared_ptr<render::MarschnerTextures> marschner_;
  std::shared_ptr<LutBuild> pending_;  // a material's tables being built on a worker; null: none
  std::string materialError_;
  vk::Buffer frames_;  // framesInFlight x maxViewsPerFrame gpu::RenderFrame slots, persistently mapped
  std::uint32_t frameStride_ = 0;
  std::shared_ptr<render::HeadPass> head_;
  // The head bounce map's draw of this head (it reads bounceFrame_).
  std::unique_ptr<render::HeadBouncePass> bounce_;
  std::shared_ptr<render::StrandPass> strandPass_;  // the graphics raster's ribbons; null with the compute raster
  bool viewsDrawn_ = false;
  std::uint64_t viewFrame_ = 0;       // the frame of the views most recently drawn
  float largestViewFraction_ = 1.0f;  // their largest LOD fraction
  struct BlockWrite {
    std::uint64_t epoch, frame;  // Renderer::recordEpoch() and the frame when recordDraw last wrote the slot
  };
  std::vector<std::optional<BlockWrite>> blockWrites_;  // per View::index
};
}  // namespace hp
