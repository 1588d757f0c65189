#version 460
// The skin's bounce at a few points along every strand (compute/head/strand_bounce_pass.h), once per frame
// after the head bounce map; the shading of every view interpolates between the samples. Two steps (the
// specialization constant STEP):
// - BOUNCE_STEP_GATHER: one invocation per sample of the bound strands (the smoothed guides, or a chunk's
//   render strands in guides-only layouts), each the gather of head_bounce.glsl at the point of the strand
//   where the sample lies (bounce_samples.glsl), with the opacity-map value of shadow slot 0 there;
// - BOUNCE_STEP_BLEND: one invocation per sample of a chunk's render strands, the blend of the same sample of
//   its three guides with its barycentrics (interpolate.comp blends their positions so): a gather costs 48
//   texture reads, and the default head has 2,130 guides for its 20,000 render strands (64 strands per
//   guide at 136,320).
#include "shared/render.h"
#include "shared/strands.h"
#include "common.glsl"

layout(local_size_x = RENDER_BOUNCE_WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint STEP = BOUNCE_STEP_GATHER;
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(binding = RENDER_BINDING_BOUNCE_FLUX) uniform sampler2D bounceFlux;
layout(binding = RENDER_BINDING_BOUNCE_POSITION) uniform sampler2D bouncePosition;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_BOUNCE_SAMPLES) writeonly buffer Samples { uvec2 bounceSamples[]; };
layout(std430, binding = RENDER_BINDING_BOUNCE_GUIDE_SAMPLES) readonly buffer GuideSamples { uvec2 guideSamples[]; };
layout(std430, binding = RENDER_BINDING_STRAND_BINDINGS) readonly buffer Bindings { StrandBindingGpu bindings[]; };
layout(std430, binding = RENDER_BINDING_SCALP_TRIANGLES) readonly buffer Triangles { uvec4 triangles[]; };
layout(push_constant) uniform Push { StrandBouncePush push; };
#define HP_BOUNCE_SAMPLES_WRITER
#include "bounce_samples.glsl"
#include "head_bounce.glsl"

// Sample k of the chunk's render strand `strand`: its guides' sample k blended with its barycentrics in the
// logarithm (a weighted geometric mean). The bounce falls off steeply with the distance from the skin and
// the three guides around a strand lie at different distances from it, so a linear blend overestimates it
// (measured: +17% of the bounce against the gather along every strand; the log blend -3%, the mean of the
// two +7.5%: docs/SHADING.md "Skin bounce").
vec3 blendedSample(uint strand, uint k) {
  StrandBindingGpu b = bindings[strand];
  uvec3 guides = triangles[b.triangle].xyz * push.samples + k;
  vec3 w = vec3(b.x1, b.x2, max(0.0, 1.0 - b.x1 - b.x2));
  // Clamped to the largest half float: a zero weight times the log of an infinite sample would be NaN.
  const vec3 largest = vec3(65504.0);
  vec3 b0 = min(unpackHalfRgb(guideSamples[guides.x]), largest), b1 = min(unpackHalfRgb(guideSamples[guides.y]), largest);
  vec3 b2 = min(unpackHalfRgb(guideSamples[guides.z]), largest);
  vec3 lowest = 1e-3 * max(b0, max(b1, b2)) + 1e-30;  // keeps the logarithm finite where a sample is 0
  return exp(w.x * log(b0 + lowest) + w.y * log(b1 + lowest) + w.z * log(b2 + lowest)) - lowest;
}

vec3 gatheredSample(uint strand, uint k) {
  float along = bounceSampleVertex(k, push.samples, push.vertices);
  uint v0 = min(uint(along), push.vertices - 1u);
  uint v1 = min(v0 + 1u, push.vertices - 1u);
  uint base = strand * push.vertices;
  vec3 p = mix(positions[base + v0].xyz, positions[base + v1].xyz, along - float(v0));
  LightSample ls = sampleLight(frame.lights[frame.lightCount.y], p);  // the light of shadow slot 0
  return headBounceAt(p, ls.L, frameOpacityAlpha(0u, p, false));
}

void main() {
  uint n = hpThreadId(RENDER_BOUNCE_WORKGROUP_SIZE);
  if (n >= push.strandCount * push.samples) return;
  if (frame.headBounce.x == 0.0) {  // no light in slot 0 to bounce (the pass is not recorded then)
    bounceSamples[n] = packHalfRgb(vec3(0.0));
    return;
  }
  uint strand = n / push.samples, k = n % push.samples;
  bounceSamples[n] = packHalfRgb(STEP == BOUNCE_STEP_BLEND ? blendedSample(strand, k) : gatheredSample(strand, k));
}
