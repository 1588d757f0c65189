// A unit normal in one float of the head bounce map (octahedral, 2 x 16-bit snorm in the float's bits),
// GLSL only: written by head_bounce.frag, read by head_bounce.glsl.
#ifndef HP_HEAD_BOUNCE_ENCODING_GLSL
#define HP_HEAD_BOUNCE_ENCODING_GLSL

vec2 bounceSignNotZero(vec2 v) { return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

float bounceEncodeNormal(vec3 n) {
  vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
  if (n.z < 0.0) p = (1.0 - abs(p.yx)) * bounceSignNotZero(p);
  return uintBitsToFloat(packSnorm2x16(p));
}

vec3 bounceDecodeNormal(float f) {
  vec2 p = unpackSnorm2x16(floatBitsToUint(f));
  vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * bounceSignNotZero(n.xy);
  return normalize(n);
}
#endif
