// Opacity shadow map lookup (docs/THEORY.md §5.3, the paper's eq. 10), GLSL only, for the shading passes.
// Per vertex: the light clip (x, y, w) and the 16 interpolation weights w_i = max(0, 1 - |s - i|) of the slice
// coordinate s (shared/opacity.h), moved `bias` slices toward the light so a strand does not shadow
// itself. Per fragment: alpha = sum_i w_i alpha(z_i) as 4 dot products, T = exp(-k alpha).
// textureLod (the maps have one mip) so compute shaders can look up too.
// Per fragment the uv is clip.xy / clip.w (exact for a spot's perspective map too; ortho: w = 1).
// Outside the map's x/y box, or behind a spot (w <= 0), there is no hair: alpha = 0.
// `slot`: the light's shadow slot, whose layers start at slot x OPACITY_LAYERS (shared/opacity.h).
#ifndef HP_OPACITY_LOOKUP_GLSL
#define HP_OPACITY_LOOKUP_GLSL
#include "shared/opacity.h"

struct OpacityVertex {
  vec3 uvw;  // uv = uvw.xy / uvw.z (shared/opacity.h: clip.xy / clip.w, y flipped)
  vec4 w0, w1, w2, w3;  // slices 1-4, 5-8, 9-12, 13-16
  float s;              // the point's own slice coordinate, unbiased (deep maps: the lookup starts there); -1: off
};

// The hat weights max(0, 1 - |s - i|) of the four slices i = first .. first + 3.
vec4 opacitySliceWeights(float s, float first) {
  return max(vec4(0.0), 1.0 - abs(s - (vec4(0.0, 1.0, 2.0, 3.0) + first)));
}

// `enabled` false gives zero weights (T = 1) with the same varyings.
OpacityVertex opacityVertex(LightSpace light, vec3 world, float bias, bool enabled) {
  vec4 clip = light.viewProj * vec4(world, 1.0);
  OpacityVertex o;
  // uv = (clip.xy / w) * (0.5, -0.5) + 0.5: the pass's viewport flips y (clip +Y is up).
  o.uvw = vec3(clip.x * 0.5 + 0.5 * clip.w, 0.5 * clip.w - clip.y * 0.5, clip.w);
  // Behind z_far the last slice holds all the hair; in front of z_near (s <= 0) there is none.
  o.s = enabled ? clip.z * float(OPACITY_SLICES) : -1.0;
  float s = clamp(clip.z * float(OPACITY_SLICES) - bias, 0.0, float(OPACITY_SLICES));
  float on = enabled ? 1.0 : 0.0;
  o.w0 = on * opacitySliceWeights(s, 1.0);
  o.w1 = on * opacitySliceWeights(s, 5.0);
  o.w2 = on * opacitySliceWeights(s, 9.0);
  o.w3 = on * opacitySliceWeights(s, 13.0);
  return o;
}

// The map's uv of a lookup; false outside the map's x/y box or behind a spot (no hair there: alpha = 0).
bool opacityUv(vec3 uvw, out vec2 uv) {
  uv = uvw.xy / uvw.z;
  return uvw.z > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// One of the soft lookups' 4 taps: 1.5 texels from the receiver diagonally.
vec3 opacitySoftTap(sampler2DArray maps, vec3 uvw, int k) {
  vec2 d = 1.5 / vec2(textureSize(maps, 0).xy);
  return vec3(uvw.xy + vec2((k & 1) == 0 ? -d.x : d.x, k < 2 ? -d.y : d.y) * uvw.z, uvw.z);
}

float opacityAlpha(sampler2DArray maps, uint slot, vec3 uvw, vec4 w0, vec4 w1, vec4 w2, vec4 w3) {
  vec2 uv;
  if (!opacityUv(uvw, uv)) return 0.0;
  float l = float(slot * OPACITY_LAYERS);
  return dot(w0, textureLod(maps, vec3(uv, l), 0.0)) + dot(w1, textureLod(maps, vec3(uv, l + 1.0), 0.0)) +
         dot(w2, textureLod(maps, vec3(uv, l + 2.0), 0.0)) + dot(w3, textureLod(maps, vec3(uv, l + 3.0), 0.0));
}
// The same over a wider footprint for opaque receivers (the head): 4 bilinear taps 1.5 texels from the
// receiver diagonally, a box of ~5 texels. One render strand covers about one texel, so the plain lookup draws
// each strand's shadow as a sharp line on the skin; hair shadows on skin come from many fibres and are
// soft. (Strand receivers keep the sharp lookup: it is what separates strands from the ones above them.)
float opacityAlphaSoft(sampler2DArray maps, uint slot, vec3 uvw, vec4 w0, vec4 w1, vec4 w2, vec4 w3) {
  if (!(uvw.z > 0.0)) return 0.0;
  float sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += opacityAlpha(maps, slot, opacitySoftTap(maps, uvw, k), w0, w1, w2, w3);
  return 0.25 * sum;
}

// Deep opacity maps (OpacitySettings::deep, shared/opacity.h): the slices start at the first hair of the
// texel the point falls in (nearest texel of the last layer), so the weights are made here from the
// point's slice coordinate s (OpacityVertex::s) rather than per vertex. bias: in deep slices.
float opacityAlphaDeep(sampler2DArray maps, uint slot, vec3 uvw, float s, float bias) {
  vec2 uv;
  if (s < 0.0 || !opacityUv(uvw, uv)) return 0.0;
  ivec2 size = textureSize(maps, 0).xy;
  ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
  float s0 = texelFetch(maps, ivec3(texel, int(slot * OPACITY_LAYERS + OPACITY_TARGETS)), 0).x;
  float d = clamp((s - s0) * OPACITY_DEEP_FACTOR - bias, 0.0, float(OPACITY_SLICES));
  return opacityAlpha(maps, slot, uvw, opacitySliceWeights(d, 1.0), opacitySliceWeights(d, 5.0), opacitySliceWeights(d, 9.0),
                      opacitySliceWeights(d, 13.0));
}

// opacityAlphaSoft's 4 taps for deep maps (opaque receivers: the head).
float opacityAlphaDeepSoft(sampler2DArray maps, uint slot, vec3 uvw, float s, float bias) {
  if (!(uvw.z > 0.0)) return 0.0;
  float sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += opacityAlphaDeep(maps, slot, opacitySoftTap(maps, uvw, k), s, bias);
  return 0.25 * sum;
}
#endif
