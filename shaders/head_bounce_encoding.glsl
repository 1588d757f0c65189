// A unit normal in one float of the head bounce map, GLSL only: written by head_bounce.frag, read by
// head_bounce.glsl. Octahedral, 11 bits per coordinate, packed into an integer below 2^22 and stored as that
// float (exact: floats hold every integer below 2^24), so the value is always finite and normal, never a
// NaN or denormal pattern that raw bit casts can make.
#ifndef HP_HEAD_BOUNCE_ENCODING_GLSL
#define HP_HEAD_BOUNCE_ENCODING_GLSL

vec2 bounceSignNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

float bounceEncodeNormal(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  if (n.z < 0.0) p = (1.0 - abs(p.yx)) * bounceSignNotZero(p);
  uvec2 q = uvec2(round(clamp(p * 0.5 + 0.5, 0.0, 1.0) * 2047.0));
  return float(q.x * 2048u + q.y);
}

vec3 bounceDecodeNormal(float f) {
  uint v = uint(f);
  vec2 p = vec2(float(v >> 11u), float(v & 2047u)) / 2047.0 * 2.0 - 1.0;
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * bounceSignNotZero(n.xy);
  return normalize(n);
}
#endif
