#version 460
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
// Compute rasterizer, per render vertex of a chunk: project to pixels (x, y, NDC depth, width in pixels)
// and reduce the NDC depth range of the vertices in front of the camera into RasterState for the depth
// bins. Shading waits for the binning (raster_shade.comp): only listed vertices are shaded. With motion
// vectors (specialization constant MOTION), also each vertex's screen motion: its unjittered pixel position
// now minus the one its previous position had under the previous frame's camera (shared/raster.h).
#include "shared/render.h"
#include "shared/strands.h"
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint MOTION = 0u;
// Read-only storage blocks, not uniform blocks or push constants: Mesa 22.3's lavapipe inlines uniform
// values that steer branches or loops into a fresh shader variant on every bind (one LLVM compile per
// dispatch; docs/DESIGN.md driver notes). Same std140 layout; no cost on GPUs (read uniformly).
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Attributes { StrandAttributes attributes[]; };
layout(std430, binding = RASTER_BINDING_SCREEN) writeonly buffer Screen { vec4 screen[]; };
layout(std430, binding = RASTER_BINDING_STATE) buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_PREVIOUS) readonly buffer Previous { vec4 previous[]; };
layout(std430, binding = RASTER_BINDING_MOTION) writeonly buffer Motion { uint motion[]; };

// Pixel position (origin top left) of NDC x, y: the graphics passes' viewport flips y (clip +Y is up), so
// pixel rows go down.
vec2 pixelOf(vec2 ndc) { return vec2((ndc.x * 0.5 + 0.5) * float(params.width), (0.5 - ndc.y * 0.5) * float(params.height)); }

// The vertex's screen motion in pixels: now (unjittered) minus before; 0 where either is behind a camera.
vec2 screenMotion(uint i, vec2 pixelNow, float w) {
  vec4 before = frame.previousViewProj * vec4(previous[i].xyz, 1.0);
  if (!(before.w > 1e-6) || !(w > 1e-6)) return vec2(0.0);
  return pixelNow - frame.jitter.xy - pixelOf(before.xy / before.w);
}

void main() {
  uint q = params.verticesPerStrand;
  // NDC depth in [0, 1] is non-negative, so its float bits order like the values; none: the largest uint.
  uint depthBits = 0xFFFFFFFFu;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  if (i < params.strandCount * q) {
    uint global = params.firstVertex + i;
    vec4 pos = positions[i];
    vec4 clip = frame.proj * frame.view * vec4(pos.xyz, 1.0);
    if (params.reversedDepth != 0u) clip.z = clip.w - clip.z;  // near 0, far 1, as the head's depth is read
    // Behind the camera, or not finite (a NaN guide's strands): no footprint, and kept out of the depth range
    // (a NaN's bits would order past every depth and widen the bins for the whole frame).
    if (!allFinite(clip) || clip.w <= 1e-6 || clip.z < 0.0) {
      screen[global] = vec4(0.0, 0.0, 1.0, -1.0);
      if (MOTION != 0u) motion[global] = 0u;
    } else {
      vec3 ndc = clip.xyz / clip.w;
      vec2 pixel = pixelOf(ndc.xy);
      if (MOTION != 0u) motion[global] = packHalf2x16(screenMotion(i, pixel, clip.w));
      float width = frame.strand.x * attributes[i / q].widthScale * mix(1.0, frame.strand.y, pos.w);
      screen[global] = vec4(pixel, ndc.z, width / (frame.cameraPosition.w * clip.w));
      depthBits = floatBitsToUint(ndc.z);
    }
  }
  // The subgroup's range, then one atomic pair per subgroup on the frame's (no shared memory or barrier).
  uint nearest = subgroupMin(depthBits);
  uint farthest = subgroupMax(depthBits == 0xFFFFFFFFu ? 0u : depthBits);
  if (subgroupElect() && nearest <= farthest) {
    atomicMin(state.depthBits.x, nearest);
    atomicMax(state.depthBits.y, farthest);
  }
}
