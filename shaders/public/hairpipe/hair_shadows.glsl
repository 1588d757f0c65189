// hairpipe's hair shadows in an application's own shaders (installed as <hairpipe/hair_shadows.glsl>; docs/API.md
// "Hair shadows in your shaders"): what fraction of a light reaches a point through the hair, from the opacity
// shadow maps hairpipe builds each frame (Renderer::hairShadows() gives the image, sampler, light-space buffer
// and the parameters below). hairpipe's own shading passes use these same functions.
//
// Every name it defines starts with hairpipe / Hairpipe / HAIRPIPE_. It includes nothing; the constants are
// plain #defines so that hairpipe's C++ reads the same values (the block before the GLSL-only part).
//
// The lookup (the paper's eq. 10): at a point's light clip (x, y, w), alpha = sum_i w_i alpha(z_i) with the
// hat weights w_i = max(0, 1 - |s - i|) of its slice coordinate s, moved `bias` slices toward the light so a
// receiver does not shadow itself; the light passes T = exp(-k alpha). Outside the map's x/y box, in front of
// the first slice or behind a spot (w <= 0) there is no hair: alpha = 0, T = 1.
#ifndef HAIRPIPE_HAIR_SHADOWS_GLSL
#define HAIRPIPE_HAIR_SHADOWS_GLSL

// The maps: a 2D-array image, HAIRPIPE_SHADOW_LAYERS layers per shadow slot from layer slot x that: 4 RGBA
// layers of the 16 slices (slice i: layer (i - 1) / 4, channel (i - 1) % 4, alpha(z_i) summed up to it),
// then the deep maps' first hair (its slice coordinate in .x; HAIRPIPE_SHADOW_NO_HAIR where none).
#define HAIRPIPE_SHADOW_SLICES 16
#define HAIRPIPE_SHADOW_SLICE_LAYERS 4
#define HAIRPIPE_SHADOW_LAYERS 5
#define HAIRPIPE_SHADOW_DEEP_FACTOR 4.0
#define HAIRPIPE_SHADOW_NO_HAIR 1.0e4

#ifndef __cplusplus
// One shadow slot's framing, as hairpipe writes it each frame (element `slot` of the light-space buffer,
// std430: 128 bytes). viewProj: world to the light's clip space (orthographic for a directional light,
// perspective for a spot or point light); the slice coordinate is clip.z x 16.
struct HairpipeLightSpace {
  mat4 viewProj;
  vec4 depthRange;  // x = z_near, y = z_far of the light depth, z = (z_far - z_near) / 16, w = its inverse
  vec4 extent;      // the light-space box the map covers
  uvec4 reserved0;  // hairpipe's reduction state
  uvec4 reserved1;
};

// A point in a light's maps: uvw, the map's uv times w (uv = uvw.xy / uvw.z: clip.xy / clip.w, y flipped),
// and s, its slice coordinate (unbiased; deep maps measure it from the texel's first hair).
struct HairpipeShadowPoint {
  vec3 uvw;
  float s;
};

HairpipeShadowPoint hairpipeShadowPoint(mat4 lightViewProj, vec3 world) {
  vec4 clip = lightViewProj * vec4(world, 1.0);
  // uv = (clip.xy / w) * (0.5, -0.5) + 0.5: the maps' viewport flips y (clip +Y is up).
  return HairpipeShadowPoint(vec3(clip.x * 0.5 + 0.5 * clip.w, 0.5 * clip.w - clip.y * 0.5, clip.w),
                             clip.z * float(HAIRPIPE_SHADOW_SLICES));
}

// The hat weights max(0, 1 - |s - i|) of the four slices i = first .. first + 3.
vec4 hairpipeSliceWeights(float s, float first) {
  return max(vec4(0.0), 1.0 - abs(s - (vec4(0.0, 1.0, 2.0, 3.0) + first)));
}

// The map's uv of a lookup; false outside the map's x/y box or behind a spot (no hair there: alpha = 0).
bool hairpipeShadowUv(vec3 uvw, out vec2 uv) {
  uv = uvw.xy / uvw.z;
  return uvw.z > 0.0 && all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
}

// sum_i w_i alpha(z_i) at slice coordinate d in [0, 16]: the hat weights touch at most the slices floor(d)
// and floor(d) + 1, which lie in the RGBA layer a = floor((d - 1) / 4) (clamped; slices 4a + 1 .. 4a + 4)
// and, for d in [4a + 4, 4a + 5), the next one: only those are fetched, the other layers' weights being all
// 0 (the same sum as over all four). textureLod: the maps have one mip, and compute shaders look up too.
float hairpipeAlphaAtSlice(sampler2DArray maps, uint slot, vec2 uv, float d) {
  const int last = HAIRPIPE_SHADOW_SLICE_LAYERS - 1;
  int a = clamp(int(floor((d - 1.0) * 0.25)), 0, last), b = min(a + 1, last);
  float l = float(slot * uint(HAIRPIPE_SHADOW_LAYERS));
  float alpha = dot(hairpipeSliceWeights(d, float(4 * a + 1)), textureLod(maps, vec3(uv, l + float(a)), 0.0));
  if (b != a && d > float(4 * a + 4))
    alpha += dot(hairpipeSliceWeights(d, float(4 * b + 1)), textureLod(maps, vec3(uv, l + float(b)), 0.0));
  return alpha;
}

// The opacity at a point (its uvw and s), its slice coordinate moved `bias` slices toward the light. Deep
// maps (`deep`): the slices start at the first hair of the texel the point falls in (nearest texel of the
// fifth layer) and are HAIRPIPE_SHADOW_DEEP_FACTOR finer; bias is then in deep slices. In front of the maps
// (s < 0) there is no hair.
float hairpipeShadowAlpha(sampler2DArray maps, uint slot, vec3 uvw, float s, bool deep, float bias) {
  vec2 uv;
  if (s < 0.0 || !hairpipeShadowUv(uvw, uv)) return 0.0;
  float d = s - bias;
  if (deep) {
    ivec2 size = textureSize(maps, 0).xy;
    ivec2 texel = clamp(ivec2(uv * vec2(size)), ivec2(0), size - 1);
    float s0 = texelFetch(maps, ivec3(texel, int(slot) * HAIRPIPE_SHADOW_LAYERS + HAIRPIPE_SHADOW_SLICE_LAYERS), 0).x;
    d = (s - s0) * HAIRPIPE_SHADOW_DEEP_FACTOR - bias;
  }
  // At or in front of the first slice (a deep map's texel without hair: s0 = HAIRPIPE_SHADOW_NO_HAIR) every
  // hat weight is 0: skip the layers' fetches (the lit side of the hair, receivers the hair does not shade).
  if (!(d > 0.0)) return 0.0;
  return hairpipeAlphaAtSlice(maps, slot, uv, min(d, float(HAIRPIPE_SHADOW_SLICES)));
}

// One of the soft lookup's 4 taps: 1.5 texels from the receiver diagonally.
vec3 hairpipeSoftTap(sampler2DArray maps, vec3 uvw, int k) {
  vec2 d = 1.5 / vec2(textureSize(maps, 0).xy);
  return vec3(uvw.xy + vec2((k & 1) == 0 ? -d.x : d.x, k < 2 ? -d.y : d.y) * uvw.z, uvw.z);
}

// The same over a wider footprint, for opaque receivers (skin, cloth): 4 bilinear taps 1.5 texels from the
// receiver diagonally, a box of ~5 texels. One render strand covers about one texel, so the plain lookup
// draws each strand's shadow as a sharp line on a surface, where hair shadows come from many fibres and are
// soft. (hairpipe's strands keep the sharp lookup: it separates a strand from the ones above it.)
float hairpipeShadowAlphaSoft(sampler2DArray maps, uint slot, vec3 uvw, float s, bool deep, float bias) {
  if (!(uvw.z > 0.0)) return 0.0;
  float sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += hairpipeShadowAlpha(maps, slot, hairpipeSoftTap(maps, uvw, k), s, deep, bias);
  return 0.25 * sum;
}

// What light crossing optical depth tau of hair keeps, arriving at an opaque, diffuse receiver: the
// unscattered part exp(-tau) and, with dual scattering, what the hair on the way passes on forward,
// weight x max(exp(-tau (1 - albedo)) - exp(-tau), 0) (forward: Instance::hairShadowForward(), rgb = albedo,
// a = weight; all 0 without dual scattering).
vec3 hairpipeHairTransmittance(float tau, vec4 forward) {
  float unscattered = exp(-tau);
  return unscattered + forward.a * max(exp(-tau * (1.0 - forward.rgb)) - unscattered, vec3(0.0));
}

// The one call an application's receiver makes: the light of shadow slot `slot` that reaches `world` through
// the hair, per colour channel, soft (over a few texels, for surfaces). params: Renderer::HairShadows'
// opacityScale (k), bias, deep (0 or 1) and a 4th value left 0; forward as above.
vec3 hairpipeHairShadow(sampler2DArray maps, HairpipeLightSpace light, uint slot, vec3 world, vec4 params,
                        vec4 forward) {
  HairpipeShadowPoint p = hairpipeShadowPoint(light.viewProj, world);
  float alpha = hairpipeShadowAlphaSoft(maps, slot, p.uvw, p.s, params.z != 0.0, params.y);
  return hairpipeHairTransmittance(params.x * alpha, forward);
}
#endif
#endif
