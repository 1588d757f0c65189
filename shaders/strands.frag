#version 460
// Hair shading per fragment: hairRadiance (hair_shading.glsl, the same entry point as the compute
// rasterizer's): every light of the frame with its shadows looked up at the fragment (frame_shadows.glsl),
// the ambient and the skin's bounce (interpolated from the vertex shader's). The ribbon's pixel coverage becomes a sample mask with MSAA (dithered
// per strand and pixel, see coverageMask), alpha without.
#include "shared/render.h"
#include "shared/marschner.h"
#include "shared/strands.h"

layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std140, binding = RENDER_BINDING_MARSCHNER) readonly buffer Marschner { MarschnerParams marschner; };
#include "marschner.glsl"  // after `marschner`: its table functions read the block in place
layout(binding = RENDER_BINDING_LUT_M) uniform sampler2D lutM;
layout(binding = RENDER_BINDING_LUT_N0) uniform sampler2D lutN0;
layout(binding = RENDER_BINDING_LUT_N1) uniform sampler2D lutN1;
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inTangent;
layout(location = 2) in float inCoverage;
layout(location = 3) in float inColorScale;
layout(location = 4) flat in uint inStrand;
layout(location = 5) in vec3 inBounce;
layout(location = 6) flat in float inRandom;
layout(push_constant) uniform Push { StrandDrawPush push; };
layout(location = 0) out vec4 outColor;
#include "hair_shading.glsl"

// Coverage c of n samples as a mask of round(c n + dither) bits, rotated by a hash of the strand and
// the pixel. Plain alpha-to-coverage gives every strand with the same alpha the same mask, so stacked
// sub-pixel strands keep hitting the same samples and a head of hair stays see-through; rotated masks
// let coverage accumulate the way overlapping hairs do.
uint coverageMask(float coverage, uint samples) {
  uint h = strandHash(inStrand * 9781u ^ strandHash(uint(gl_FragCoord.x) + 4099u * uint(gl_FragCoord.y)));
  uint bits = min(uint(coverage * float(samples) + float(h & 0xFFFFu) / 65536.0), samples);
  uint full = (1u << samples) - 1u;
  uint mask = (1u << bits) - 1u;
  uint rotate = (h >> 16u) % samples;
  return ((mask << rotate) | (mask >> (samples - rotate))) & full;
}

void main() {
  // The mask first: a fragment whose coverage rounds to no sample is dropped before it is shaded (at small
  // sizes most of a thin strand's fragments are).
  uint mask = push.samples > 1u ? coverageMask(inCoverage, push.samples) : 0xFFFFFFFFu;
  if (mask == 0u) discard;
  // A shader that writes the sample mask on one path must write it on all: left unwritten it is undefined.
  gl_SampleMask[0] = int(mask);
  float tilt = strandTilt(inRandom, marschner.caustic.z);
  float roughness = strandRoughness(inRandom, marschner.caustic.w);
  // The graphics raster draws the head in the same pass and cannot read its depth: the far side stays open.
  vec3 radiance = hairRadiance(inWorld, inTangent, inColorScale, tilt, roughness, 0.0, inBounce);
  outColor = vec4(radiance, push.samples > 1u ? 1.0 : inCoverage);
}
