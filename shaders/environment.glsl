// The environment light of the frame (shaders/shared/environment.h): the cosine-weighted mean radiance over
// the hemisphere around n, from frame.environment's convolved SH. Never negative: an order-2 projection of
// a high-contrast environment rings below zero on its dark side. The includer declares `frame` (RenderFrame).
#ifndef HP_ENVIRONMENT_GLSL
#define HP_ENVIRONMENT_GLSL
#include "shared/environment.h"

// The SH sum's even bands (0 and 2) and its odd band (1) at n: Y_l(-n) = (-1)^l Y_l(n), so the sums at n and
// at -n share every term. Written out rather than looped: lavapipe runs shaders with loops markedly slower
// (docs/PERFORMANCE.md).
vec3 environmentEvenBands(vec3 n) {
  return frame.environment[0].rgb * envShBasis(0u, n) + frame.environment[4].rgb * envShBasis(4u, n) +
         frame.environment[5].rgb * envShBasis(5u, n) + frame.environment[6].rgb * envShBasis(6u, n) +
         frame.environment[7].rgb * envShBasis(7u, n) + frame.environment[8].rgb * envShBasis(8u, n);
}
vec3 environmentOddBand(vec3 n) {
  return frame.environment[1].rgb * envShBasis(1u, n) + frame.environment[2].rgb * envShBasis(2u, n) +
         frame.environment[3].rgb * envShBasis(3u, n);
}

vec3 environmentLight(vec3 n) { return max(environmentEvenBands(n) + environmentOddBand(n), vec3(0.0)); }

// environmentLight at n and at -n (a fibre's two sides) from one evaluation of the basis.
void environmentLightBothSides(vec3 n, out vec3 atN, out vec3 opposite) {
  vec3 even = environmentEvenBands(n), odd = environmentOddBand(n);
  atN = max(even + odd, vec3(0.0));
  opposite = max(even - odd, vec3(0.0));
}
#endif
