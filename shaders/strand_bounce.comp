#version 460
// The skin's bounce at a few points along every strand (compute/head/strand_bounce_pass.h): one invocation
// per sample of a chunk's strands, each the gather of head_bounce.glsl at the point of the strand where the
// sample lies (bounce_samples.glsl), with the opacity-map value of shadow slot 0 there. Once per frame after
// the head bounce map; the shading of every view interpolates between the samples.
#include "shared/render.h"
#include "shared/strands.h"
#include "common.glsl"

layout(local_size_x = RENDER_BOUNCE_WORKGROUP_SIZE) in;
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(binding = RENDER_BINDING_BOUNCE_FLUX) uniform sampler2D bounceFlux;
layout(binding = RENDER_BINDING_BOUNCE_POSITION) uniform sampler2D bouncePosition;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_BOUNCE_SAMPLES) writeonly buffer Samples { uvec2 bounceSamples[]; };
layout(push_constant) uniform Push { StrandBouncePush push; };
#define HP_BOUNCE_SAMPLES_WRITER
#include "bounce_samples.glsl"
#include "head_bounce.glsl"

void main() {
  uint n = hpThreadId(RENDER_BOUNCE_WORKGROUP_SIZE);
  if (n >= push.strandCount * push.samples) return;
  if (frame.headBounce.x == 0.0) {  // no light in slot 0 to bounce (the pass is not recorded then)
    bounceSamples[n] = packHalfRgb(vec3(0.0));
    return;
  }
  uint strand = n / push.samples, k = n % push.samples;
  float along = bounceSampleVertex(k, push.samples, push.vertices);
  uint v0 = min(uint(along), push.vertices - 1u);
  uint v1 = min(v0 + 1u, push.vertices - 1u);
  uint base = strand * push.vertices;
  vec3 p = mix(positions[base + v0].xyz, positions[base + v1].xyz, along - float(v0));
  LightSample ls = sampleLight(frame.lights[frame.lightCount.y], p);  // the light of shadow slot 0
  bounceSamples[n] = packHalfRgb(headBounceAt(p, ls.L, frameOpacityAlpha(0u, p, false)));
}
