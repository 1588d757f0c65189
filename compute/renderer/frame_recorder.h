#pragma once
// Contract: the barriers between hairpipe's passes, in one place (the passes insert none). The Renderer
// records through these; they are public so tests can drive the passes over hand-made strands with the
// same synchronization.
//   recordUpdatePasses   simulate -> tessellate -> interpolate of every instance, batched per pass, with
//                        the copies of the positions into the previous positions where kept.
//                        Before: nothing (the previous frame's draws and compute are ordered here).
//                        After: render strands in ComputeWrite, previous positions in TransferDst.
//   recordShadowPasses   bounds of every caster into the shared LightSpace, one finalize, then every
//                        caster's strands and head into the shared opacity maps (drawn, or splatted in
//                        compute and resolved: OpacitySettings::raster). The strand positions'
//                        last ComputeWrite must be made visible to VertexRead first (makeStrandsDrawable);
//                        this adds ComputeRead for the bounds and splats. Leaves LightSpace in
//                        BufferUse::GraphicsRead (and ComputeRead) and the maps in ImageUse::FragmentSampled.
//   recordStrandBounce   the skin's bounce along each instance's strands, after the head bounce map was drawn.
//                        Before: this frame's opacity maps and head bounce map in ImageUse::FragmentSampled,
//                        the bounce frame blocks in ComputeRead. After: the maps as before, the bounce
//                        samples readable by the shading (BufferUse::ComputeRead and VertexRead).
#include "hairpipe_volk.h"

#include <glm/glm.hpp>

#include <span>

#include "compute/shadows/bounds_pass.h"
#include "compute/strands/interpolate_pass.h"
#include "compute/strands/simulate_pass.h"
#include "compute/strands/tessellate_pass.h"
#include "engine/core/hair/scene.h"
#include "compute/head/strand_bounce_pass.h"
#include "compute/shadows/opacity_pass.h"
#include "compute/shadows/shadow_maps.h"
#include "engine/vk/profiler.h"

namespace hp {
struct UpdateWork {
  SimulatePass* simulate;
  HeadMotion motion;
  const compute::TessellatePass* tessellate;
  const compute::InterpolatePass* interpolate;
  // Buffers that keep previous positions (StrandBuffers::keepsPrevious), or null; `primed`: they hold a
  // frame, so the copy goes before interpolate (otherwise after it: no motion on a first frame).
  const compute::StrandBuffers* strands = nullptr;
  bool primed = false;
};

struct ShadowCaster {
  const compute::BoundsPass* bounds;
  const render::OpacityPass* opacity;
  glm::mat4 headToWorld{1.0f};
  glm::vec2 strandWidth{0.0005f, 0.35f};  // root width, tip / root: the instance's LookSettings (footprint)
  std::uint32_t strandLimit = compute::kAllStrands;  // the level of detail's prefix of the strands
};

void recordUpdatePasses(const vk::Context& ctx, VkCommandBuffer cmd, std::span<const UpdateWork> work,
                        vk::GpuProfiler* profiler = nullptr);
// The render strands' compute writes become visible to the vertex stage (shadows and draws).
void makeStrandsDrawable(const vk::Context& ctx, VkCommandBuffer cmd);

compute::ShadowLight shadowLightOf(const LightSpec& light);
// headView on: the casters' heads are also drawn into the maps' head depth map (left FragmentSampled).
void recordShadowPasses(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const ShadowCaster> casters,
                        const compute::ShadowLight& light, const compute::BoundsFraming& framing,
                        vk::GpuProfiler* profiler = nullptr, const render::HeadShadowView& headView = {});
void recordStrandBounce(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const render::StrandBouncePass* const> passes);
}  // namespace hp
