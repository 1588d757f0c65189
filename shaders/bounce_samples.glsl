// The skin's bounce sampled along each strand (shared/render.h RENDER_BINDING_BOUNCE_SAMPLES), GLSL only:
// where sample k of a strand lies (strand_bounce.comp writes it) and the bounce at a vertex, interpolated
// between the two samples around it (raster_shade.comp per vertex, strands.vert for the ribbons).
// The samples are evenly spaced in the vertex index: sample k at vertex k (Q - 1) / (K - 1), so the first is
// the root and the last the tip; K = Q samples every vertex. The reader declares `bounceSamples`
// (uvec2[]) and `frame` (RenderFrame: headBounce.x on, headBounce.z = K).
#ifndef HP_BOUNCE_SAMPLES_GLSL
#define HP_BOUNCE_SAMPLES_GLSL
#include "half_rgb.glsl"

// Sample k's position along the strand, in vertices (continuous).
float bounceSampleVertex(uint k, uint samples, uint vertices) {
  return float(k) * float(vertices - 1u) / float(max(samples, 2u) - 1u);
}

#ifndef HP_BOUNCE_SAMPLES_WRITER
// The bounce at vertex `vertex` of the chunk's strand `strand` (0 when the frame has none): halfway between
// the chord and the exponential through the two samples around it. The bounce falls off convexly along a
// strand that hangs near the skin, so the chord overestimates it there and the exponential underestimates
// it (against the gather at every vertex, docs/SHADING.md "Skin bounce").
vec3 bounceAlongStrand(uint strand, uint vertex, uint vertices) {
  if (frame.headBounce.x == 0.0) return vec3(0.0);
  uint samples = uint(frame.headBounce.z);
  float t = float(vertex) * float(samples - 1u) / float(vertices - 1u);
  uint k = min(uint(t), samples - 2u);  // the samples k and k + 1 around t
  uint base = strand * samples;
  vec3 b0 = unpackHalfRgb(bounceSamples[base + k]), b1 = unpackHalfRgb(bounceSamples[base + k + 1u]);
  float f = t - float(k);
  // A floor relative to the larger sample keeps the logarithm finite where a sample is 0 and the blend the
  // same at any brightness (a fixed floor made it depend on the light's intensity).
  vec3 lowest = 1e-3 * max(b0, b1) + 1e-30;
  vec3 exponential = exp(mix(log(b0 + lowest), log(b1 + lowest), f)) - lowest;
  return 0.5 * (mix(b0, b1, f) + exponential);
}
#endif
#endif
