// The head as an opaque occluder (compute/shadows/shadow_maps.h, head_shadow_view.h), GLSL only, for the shading
// passes: a depth map of the head's BACK faces seen from the light ("second depth"), so a lit surface
// never shadows itself and the wrap-lit side just past the terminator is not cut off by its own
// front; only another part of the head (or the head for hair behind it) occludes. One layer per shadow
// slot. The receiver moves `offset` toward the light, then 3 x 3 bilinearly filtered depth-compare taps one
// texel apart: a smooth penumbra over ~4 texels, no slice quantisation. Outside the map: lit (the sampler's
// white border). The taps are summed as the 4 x 4 texels they cover, in 4 gathers of 2 x 2 compares: a tap i
// texels off weighs texels b + i and b + i + 1 by (1 - f, f) (b, f: the receiver's texel and bilinear
// fraction), so over i = -1..1 texels b - 1 .. b + 2 weigh (1 - f, 1, 1, f) per axis. The same sum as 9
// filtered taps in 4 texture calls instead of 9 (and without a GPU's 8-bit filter weights).
#ifndef HP_HEAD_SHADOW_GLSL
#define HP_HEAD_SHADOW_GLSL

// slopeTan: for a surface receiver facing away from the light (its own back face is in the map), tan of
// the angle between its normal and the light; 0 for hair and lit skin. The taps up to 2 texels beside it
// read its own surface that much nearer the light per texel, so the offset grows by 2 texels (head.w) x
// slopeTan, at most 10, past the base (head.y).
float headVisibility(sampler2DArrayShadow map, uint slot, FrameShadow shadow, vec3 world, vec3 towardLight,
                     float slopeTan) {
  if (shadow.head.x == 0.0) return 1.0;
  float offset = shadow.head.y + 2.0 * shadow.head.w * min(slopeTan, 10.0);
  vec4 clip = shadow.headViewProj * vec4(world + towardLight * offset, 1.0);
  if (!(clip.w > 0.0)) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  // Same y flip as the opacity maps: the pass's viewport flips y (clip +Y is up).
  vec2 uv = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
  float ref = min(ndc.z, 1.0);  // beyond the map's far plane: compared with the far plane
  vec2 size = vec2(textureSize(map, 0).xy);  // shadow.head.z = 1 / its width: the taps are one texel apart
  vec2 t = uv * size - 0.5;
  vec2 b = floor(t), f = t - b;
  float sum = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      // Texels b - 1 + 2i, b + 2i across (and likewise down): their corner is at b + 2i in texel units.
      vec2 corner = (b + vec2(2 * i, 2 * j)) / size;
      vec4 c = textureGather(map, vec3(corner, float(slot)), ref);  // (x0,y1), (x1,y1), (x1,y0), (x0,y0)
      vec2 w0 = vec2(i == 0 ? 1.0 - f.x : 1.0, j == 0 ? 1.0 - f.y : 1.0);  // the lower texel's x, y weights
      vec2 w1 = vec2(i == 0 ? 1.0 : f.x, j == 0 ? 1.0 : f.y);              // the upper's
      sum += dot(c, vec4(w0.x * w1.y, w1.x * w1.y, w1.x * w0.y, w0.x * w0.y));
    }
  return sum / 9.0;
}
#endif
