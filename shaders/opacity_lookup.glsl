// Opacity shadow map lookup (docs/THEORY.md §5.3, the paper's eq. 10), GLSL only, for the shading passes:
// at a point's light clip (x, y, w), alpha = sum_i w_i alpha(z_i) with the interpolation weights
// w_i = max(0, 1 - |s - i|) of its slice coordinate s (shared/opacity.h), moved `bias` slices toward the light
// so a strand does not shadow itself; T = exp(-k alpha).
// textureLod (the maps have one mip) so compute shaders can look up too.
// Per fragment the uv is clip.xy / clip.w (exact for a spot's perspective map too; ortho: w = 1).
// Outside the map's x/y box, or behind a spot (w <= 0), there is no hair: alpha = 0.
// `slot`: the light's shadow slot, whose layers start at slot x OPACITY_LAYERS (shared/opacity.h).
#ifndef HP_OPACITY_LOOKUP_GLSL
#define HP_OPACITY_LOOKUP_GLSL
#include "shared/opacity.h"

// A point in a light's opacity maps: uvw as the map's uv (uv = uvw.xy / uvw.z: clip.xy / clip.w, y flipped)
// and s, its slice coordinate (unbiased; deep maps measure it from the texel's first hair).
struct OpacityPoint {
  vec3 uvw;
  float s;
};

OpacityPoint opacityPoint(LightSpace light, vec3 world) {
  vec4 clip = light.viewProj * vec4(world, 1.0);
  // uv = (clip.xy / w) * (0.5, -0.5) + 0.5: the pass's viewport flips y (clip +Y is up).
  return OpacityPoint(vec3(clip.x * 0.5 + 0.5 * clip.w, 0.5 * clip.w - clip.y * 0.5, clip.w),
                      clip.z * float(OPACITY_SLICES));
}

// The hat weights max(0, 1 - |s - i|) of the four slices i = first .. first + 3.
vec4 opacitySliceWeights(float s, float first) {
  return max(vec4(0.0), 1.0 - abs(s - (vec4(0.0, 1.0, 2.0, 3.0) + first)));
}

// The map's uv of a lookup; false outside the map's x/y box or behind a spot (no hair there: alpha = 0).
bool opacityUv(vec3 uvw, out vec2 uv) {
  uv = uvw.xy / uvw.z;
  return uvw.z > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// sum_i w_i alpha(z_i) at slice coordinate d in [0, 16]: the hat weights touch at most the slices floor(d)
// and floor(d) + 1, which lie in the RGBA layer a = floor((d - 1) / 4) (clamped; slices 4a + 1 .. 4a + 4)
// and, for d in [4a + 4, 4a + 5), the next one: only those are fetched, the other layers' weights being all
// 0 (the same sum as over all four).
float opacityAlphaAtSlice(sampler2DArray maps, uint slot, vec2 uv, float d) {
  const int last = int(OPACITY_TARGETS) - 1;
  int a = clamp(int(floor((d - 1.0) * 0.25)), 0, last), b = min(a + 1, last);
  float l = float(slot * OPACITY_LAYERS);
  float alpha = dot(opacitySliceWeights(d, float(4 * a + 1)), textureLod(maps, vec3(uv, l + float(a)), 0.0));
  if (b != a && d > float(4 * a + 4))
    alpha += dot(opacitySliceWeights(d, float(4 * b + 1)), textureLod(maps, vec3(uv, l + float(b)), 0.0));
  return alpha;
}

// The opacity-map value at a point, its slice coordinate moved `bias` slices toward the light so a strand
// does not shadow itself. Deep maps (OpacitySettings::deep, shared/opacity.h): the slices start at the first
// hair of the texel the point falls in (nearest texel of the last layer) and are OPACITY_DEEP_FACTOR finer;
// bias is then in deep slices. In front of the maps (s < 0) there is no hair.
float opacityAlpha(sampler2DArray maps, uint slot, vec3 uvw, float s, bool deep, float bias) {
  vec2 uv;
  if (s < 0.0 || !opacityUv(uvw, uv)) return 0.0;
  float d = s - bias;
  if (deep) {
    ivec2 size = textureSize(maps, 0).xy;
    ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    float s0 = texelFetch(maps, ivec3(texel, int(slot * OPACITY_LAYERS + OPACITY_TARGETS)), 0).x;
    d = (s - s0) * OPACITY_DEEP_FACTOR - bias;
  }
  // At or in front of the first slice (a deep map's texel without hair: s0 = OPACITY_NO_HAIR) every hat
  // weight is 0: skip the layers' fetches (the lit side of the hair, skin the hair does not shade).
  if (!(d > 0.0)) return 0.0;
  return opacityAlphaAtSlice(maps, slot, uv, min(d, float(OPACITY_SLICES)));
}

// One of the soft lookups' 4 taps: 1.5 texels from the receiver diagonally.
vec3 opacitySoftTap(sampler2DArray maps, vec3 uvw, int k) {
  vec2 d = 1.5 / vec2(textureSize(maps, 0).xy);
  return vec3(uvw.xy + vec2((k & 1) == 0 ? -d.x : d.x, k < 2 ? -d.y : d.y) * uvw.z, uvw.z);
}

// The same over a wider footprint for opaque receivers (the head): 4 bilinear taps 1.5 texels from the
// receiver diagonally, a box of ~5 texels. One render strand covers about one texel, so the plain lookup draws
// each strand's shadow as a sharp line on the skin; hair shadows on skin come from many fibres and are
// soft. (Strand receivers keep the sharp lookup: it is what separates strands from the ones above them.)
float opacityAlphaSoft(sampler2DArray maps, uint slot, vec3 uvw, float s, bool deep, float bias) {
  if (!(uvw.z > 0.0)) return 0.0;
  float sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += opacityAlpha(maps, slot, opacitySoftTap(maps, uvw, k), s, deep, bias);
  return 0.25 * sum;
}
#endif
