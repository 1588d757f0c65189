// The skin's bounce sampled along each strand (shared/render.h RENDER_BINDING_BOUNCE_SAMPLES), GLSL only:
// where sample k of a strand lies (strand_bounce.comp writes it) and the bounce at a vertex, interpolated
// linearly between the samples around it (raster_shade.comp per vertex, strands.vert for the ribbons).
// The samples are evenly spaced in the vertex index: sample k at vertex k (Q - 1) / (K - 1), so the first is
// the root and the last the tip; K = Q samples every vertex. The reader declares `bounceSamples`
// (uvec2[]) and `frame` (RenderFrame: headBounce.x on, headBounce.z = K).
#ifndef HP_BOUNCE_SAMPLES_GLSL
#define HP_BOUNCE_SAMPLES_GLSL

// Sample k's position along the strand, in vertices (continuous).
float bounceSampleVertex(uint k, uint samples, uint vertices) {
  return float(k) * float(vertices - 1u) / float(max(samples, 2u) - 1u);
}

uvec2 packBounce(vec3 bounce) { return uvec2(packHalf2x16(bounce.rg), packHalf2x16(vec2(bounce.b, 0.0))); }

vec3 unpackBounce(uvec2 v) { return vec3(unpackHalf2x16(v.x), unpackHalf2x16(v.y).x); }

#ifndef HP_BOUNCE_SAMPLES_WRITER
// The bounce at vertex `vertex` of the chunk's strand `strand` (0 when the frame has none).
vec3 bounceAlongStrand(uint strand, uint vertex, uint vertices) {
  if (frame.headBounce.x == 0.0) return vec3(0.0);
  uint samples = uint(frame.headBounce.z);
  float t = float(vertex) * float(samples - 1u) / float(vertices - 1u);
  uint k1 = min(uint(t), samples - 2u);  // the span [k1, k2] holding t, its neighbours k0 and k3 (clamped)
  uint k0 = k1 > 0u ? k1 - 1u : 0u, k2 = k1 + 1u, k3 = min(k2 + 1u, samples - 1u);
  uint base = strand * samples;
  vec3 b0 = unpackBounce(bounceSamples[base + k0]), b1 = unpackBounce(bounceSamples[base + k1]);
  vec3 b2 = unpackBounce(bounceSamples[base + k2]), b3 = unpackBounce(bounceSamples[base + k3]);
  // Catmull-Rom through the samples, kept within the span's two samples' range (no overshoot below 0).
  float f = t - float(k1), f2 = f * f, f3 = f2 * f;
  vec3 c = 0.5 * (2.0 * b1 + (b2 - b0) * f + (2.0 * b0 - 5.0 * b1 + 4.0 * b2 - b3) * f2 + (3.0 * b1 - b0 - 3.0 * b2 + b3) * f3);
  return clamp(c, min(b1, b2), max(b1, b2));
}
#endif
#endif
