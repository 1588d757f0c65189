// Compute rasterizer, per vertex that raster_bin.comp listed for the chunk (an indirect dispatch): the
// radiance by hairRadiance (shaders/hair_shading.glsl, the graphics path's entry point) with the
// opacity-map lookups at the vertex (strand-space shading). Vertices of segments that touch no tile
// (off-screen, behind the head's depth) are never shaded: the fine raster reads only listed segments' ends.
// The light the skin reflects onto the vertex is interpolated from the strand's bounce samples
// (bounce_samples.glsl; strand_bounce.comp gathered them from the head bounce map). Where the head lies behind the
// vertex along the view ray (its depth at the vertex's pixel), the hair beneath and the head
// hide the sky on the fibre's far side (hairRadiance's headBehind). Included by raster_shade.comp (single-sample
// head depth) and raster_shade_ms.comp (multisampled: raster_head_depth.glsl).
#include "shared/render.h"
#include "shared/marschner.h"
#include "shared/strands.h"
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
// Storage blocks, not uniform blocks: see raster_project.comp.
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std140, binding = RENDER_BINDING_MARSCHNER) readonly buffer Marschner { MarschnerParams marschner; };
#include "marschner.glsl"  // after `marschner`: its table functions read the block in place
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(binding = RENDER_BINDING_LUT_M) uniform sampler2D lutM;
layout(binding = RENDER_BINDING_LUT_N0) uniform sampler2D lutN0;
layout(binding = RENDER_BINDING_LUT_N1) uniform sampler2D lutN1;
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Tangents { vec4 tangents[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Attributes { StrandAttributes attributes[]; };
layout(std430, binding = RASTER_BINDING_COLORS) writeonly buffer Colors { uvec2 colors[]; };
layout(std430, binding = RASTER_BINDING_SHADE_LIST) readonly buffer ShadeList { uint shadeList[]; };
layout(std430, binding = RASTER_BINDING_SHADE_ARGS) readonly buffer ShadeArgs { uvec4 shadeArgs[]; };
layout(std430, binding = RENDER_BINDING_BOUNCE_SAMPLES) readonly buffer BounceSamples { uvec2 bounceSamples[]; };
layout(std430, binding = RASTER_BINDING_SCREEN) readonly buffer Screen { vec4 screen[]; };
#include "raster_head_depth.glsl"
#include "hair_shading.glsl"
#include "bounce_samples.glsl"

// 1 where the head lies behind a vertex at screen position `s` (raster_project.comp: pixel, depth), else 0.
// One sample of its pixel: the vertex stands for a segment's end across pixels, and the term it steers is
// smooth; the samples of the head's edge would cost lavapipe 12% of the shade pass for nothing to see.
float headBehindAt(vec4 s) {
  ivec2 pixel = ivec2(floor(s.xy));
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, headDepthSize()))) return 0.0;  // off-screen
  float d = headDepthAt(pixel, 0u);
  return d < 1.0 && d > s.z ? 1.0 : 0.0;
}

void main() {
  uint n = hpThreadId(RASTER_WORKGROUP_SIZE);
  if (n >= shadeArgs[params.chunkIndex].w) return;
  uint global = shadeList[params.firstVertex + n];
  uint i = global - params.firstVertex;
  vec4 pos = positions[i];
  uint q = params.verticesPerStrand, strand = i / q;
  vec3 bounce = bounceAlongStrand(strand, i - strand * q, q);
  StrandAttributes a = attributes[strand];
  float tilt = strandTilt(a.random, marschner.caustic.z);
  float roughness = strandRoughness(a.random, marschner.caustic.w);
  float headBehind = frame.headBounce.w != 0.0 ? headBehindAt(screen[global]) : 0.0;
  vec3 radiance = hairRadiance(pos.xyz, tangents[i].xyz, a.colorScale, tilt, roughness, headBehind, bounce);
  colors[global] = packHalfRgb(radiance);
}
