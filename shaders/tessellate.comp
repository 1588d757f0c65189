#version 460
// Tessellation (docs/THEORY.md §1.3): every guide of P particles becomes Q vertices on the C1 chain of
// cubic Beziers through its particles. One invocation per output vertex (guide g, vertex j).
// Tangents at particles: central differences, one-sided at root and tip. Segment i between p_i and
// p_(i+1), d = p_(i+1) - p_i: b0 = p_i, b1 = p_i + t_i |d|/3, b2 = p_(i+1) - t_(i+1) |d|/3, b3 = p_(i+1).
// The vertex tangent is the normalised derivative; both segments meeting at a particle have the
// particle's tangent there, so tangents are continuous. Particle vertices use u = 0 (or u = 1 at the
// tip), where the Bernstein weights are exactly (1,0,0,0) / (0,0,0,1): particles are hit exactly.
#include "shared/strands.h"
#include "common.glsl"

layout(local_size_x = TESSELLATE_WORKGROUP_SIZE) in;
layout(std430, binding = TESSELLATE_BINDING_PARTICLES) readonly buffer Particles { vec4 particles[]; };
layout(std430, binding = TESSELLATE_BINDING_POSITIONS) writeonly buffer Positions { vec4 positions[]; };
layout(std430, binding = TESSELLATE_BINDING_TANGENTS) writeonly buffer Tangents { vec4 tangents[]; };
layout(push_constant) uniform Push { TessellatePush push; };

vec3 particle(uint base, uint i) { return particles[base + i].xyz; }

vec3 safeNormalize(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return len2 > 1e-30 ? v * inversesqrt(len2) : fallback;
}

// Unit tangent at particle i: central difference inside, one-sided at the ends.
vec3 particleTangent(uint base, uint i) {
  uint lo = i == 0u ? 0u : i - 1u;
  uint hi = min(i + 1u, push.particles - 1u);
  return safeNormalize(particle(base, hi) - particle(base, lo), vec3(0.0, -1.0, 0.0));
}

void main() {
  uint id = hpThreadId(TESSELLATE_WORKGROUP_SIZE);
  uint Q = push.vertices;
  if (id >= push.guideCount * Q) return;
  uint g = id / Q;
  uint j = id - g * Q;
  uint base = g * push.particles;

  uint i = vertexSegment(j, push.particles, Q);
  uint k0 = particleVertex(i, push.particles, Q);
  uint k1 = particleVertex(i + 1u, push.particles, Q);
  float u = float(j - k0) / float(k1 - k0);

  vec3 p0 = particle(base, i);
  vec3 p1 = particle(base, i + 1u);
  vec3 t0 = particleTangent(base, i);
  vec3 t1 = particleTangent(base, i + 1u);
  float third = length(p1 - p0) / 3.0;
  vec3 b1 = p0 + t0 * third;
  vec3 b2 = p1 - t1 * third;

  float s = 1.0 - u;
  vec3 pos = (s * s * s) * p0 + (3.0 * s * s * u) * b1 + (3.0 * s * u * u) * b2 + (u * u * u) * p1;
  vec3 der = (s * s) * (b1 - p0) + (2.0 * s * u) * (b2 - b1) + (u * u) * (p1 - b2);
  // A zero-length segment has no derivative: fall back to the blended particle tangents.
  vec3 tan = safeNormalize(der, safeNormalize(mix(t0, t1, u), t0));

  positions[id] = vec4(pos, float(j) / float(Q - 1u));
  tangents[id] = vec4(tan, 0.0);
}
