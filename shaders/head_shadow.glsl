// The head as an opaque occluder (compute/shadows/shadow_maps.h, head_shadow_view.h), GLSL only, for the shading
// passes: a depth map of the head's BACK faces seen from the light ("second depth"), so a lit surface
// never shadows itself and the wrap-lit side just past the terminator is not cut off by its own
// front; only another part of the head (or the head for hair behind it) occludes. One layer per shadow
// slot. The receiver moves `offset` toward the light, then 3 x 3 depth-compare taps one texel apart, each
// bilinearly filtered by the sampler: a smooth penumbra over ~4 texels, no slice quantisation. Outside the
// map: lit.
#ifndef HP_HEAD_SHADOW_GLSL
#define HP_HEAD_SHADOW_GLSL

float headVisibility(sampler2DArrayShadow map, uint slot, FrameShadow shadow, vec3 world, vec3 towardLight) {
  if (shadow.head.x == 0.0) return 1.0;
  vec4 clip = shadow.headViewProj * vec4(world + towardLight * shadow.head.y, 1.0);
  if (!(clip.w > 0.0)) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  // Same y flip as the opacity maps: the pass's viewport flips y (clip +Y is up).
  vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
  float ref = min(ndc.z, 1.0);  // beyond the map's far plane: compared with the far plane
  float sum = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i)
      sum += texture(map, vec4(uv + vec2(float(i), float(j)) * shadow.head.z, float(slot), ref));
  return sum / 9.0;
}
#endif
