#version 460
// One invocation simulates one guide for one frame (docs/THEORY.md §2): per substep, pin the root to the
// moving scalp, Verlet-integrate the free particles (gravity, wind, damping, speed clamp; the hair grid's
// friction and volume when on, §2.7), pull mildly toward the rest pose, then iterate the local shape (when
// on), length constraints (Gauss-Seidel, root to tip; the last sweep follow-the-leader) and pearl
// collisions, collisions last so the final state is outside every collider, then the distance grid
// (sdf_collide.glsl), so the final state is outside the head mesh.
// tests/compute/sim_reference.cpp is the same algorithm in double precision; keep them in step.
#include "shared/simulate.h"
#include "shared/hair_grid.h"
#include "common.glsl"

layout(local_size_x = SIM_WORKGROUP_SIZE) in;
// A read-only storage block, not a uniform block: Mesa 22.3's lavapipe inlines uniform values that
// steer loops into a fresh shader variant on every bind, i.e. one LLVM compile (~20 ms, never freed)
// per simulated frame. Same std140 layout; no cost on GPUs (the block is read uniformly).
layout(std140, binding = SIM_BINDING_FRAME) readonly buffer Frame { SimFrame frame; };
layout(std430, binding = SIM_BINDING_POSITIONS) buffer Positions { vec4 positions[]; };
layout(std430, binding = SIM_BINDING_PREVIOUS) buffer Previous { vec4 previous[]; };
layout(std430, binding = SIM_BINDING_REST) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = SIM_BINDING_ROOTS) readonly buffer Roots { vec4 roots[]; };
layout(std430, binding = SIM_BINDING_ROOTS_PREV) buffer RootsPrev { vec4 rootsPrev[]; };
layout(std430, binding = SIM_BINDING_BONES) readonly buffer Bones { mat4 bones[]; };
layout(std430, binding = SIM_BINDING_SKIN) readonly buffer Skin { SkinWeights skin[]; };
#define SDF_BINDING SIM_BINDING_SDF
#include "sdf_collide.glsl"
#include "hair_grid.glsl"
layout(std430, binding = SIM_BINDING_GRID) readonly buffer Grid { vec4 grid[]; };

// Particles per guide, specialised to the asset's P when the pipeline is built, so the strand's arrays
// have their exact size and constant-bound loops can be unrolled into registers.
layout(constant_id = SIM_SPEC_PARTICLES) const uint PARTICLES = 7u;
vec3 x[PARTICLES];
vec3 xPrev[PARTICLES];

// A per-guide phase in [0, 2 pi) so gusts do not move every strand in lockstep.
float gustPhase(uint guide) {
  uint h = guide * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  return float((h >> 22u) ^ h) * (6.28318530718 / 4294967296.0);
}

vec3 transformPoint(mat4 m, vec3 p) { return (m * vec4(p, 1.0)).xyz; }

// T(position) R(q) T(-restRoot): the rest pose carried by a root frame (q unit, xyzw).
mat4 rootFrameMatrix(vec4 position, vec4 q, vec3 restRoot) {
  vec3 x = vec3(1.0 - 2.0 * (q.y * q.y + q.z * q.z), 2.0 * (q.x * q.y + q.w * q.z), 2.0 * (q.x * q.z - q.w * q.y));
  vec3 y = vec3(2.0 * (q.x * q.y - q.w * q.z), 1.0 - 2.0 * (q.x * q.x + q.z * q.z), 2.0 * (q.y * q.z + q.w * q.x));
  vec3 z = vec3(2.0 * (q.x * q.z + q.w * q.y), 2.0 * (q.y * q.z - q.w * q.x), 1.0 - 2.0 * (q.x * q.x + q.y * q.y));
  mat3 r = mat3(x, y, z);
  return mat4(vec4(x, 0.0), vec4(y, 0.0), vec4(z, 0.0), vec4(position.xyz - r * restRoot, 1.0));
}

mat4 skinned(uint guide, uint first) {
  SkinWeights s = skin[guide];
  return bones[first + s.bones.x] * s.weights.x + bones[first + s.bones.y] * s.weights.y +
         bones[first + s.bones.z] * s.weights.z + bones[first + s.bones.w] * s.weights.w;
}

// The guide's root matrix at the start and at the end of the frame (see shared/simulate.h).
void rootMatrices(uint guide, uint base, out mat4 from, out mat4 to) {
  if (frame.scalpMode == SIM_SCALP_ROOT_FRAMES) {
    vec3 restRoot = rest[base].xyz;
    from = rootFrameMatrix(rootsPrev[2u * guide], rootsPrev[2u * guide + 1u], restRoot);
    to = rootFrameMatrix(roots[2u * guide], roots[2u * guide + 1u], restRoot);
    rootsPrev[2u * guide] = roots[2u * guide];  // this invocation alone owns its guide's entries
    rootsPrev[2u * guide + 1u] = roots[2u * guide + 1u];
  } else if (frame.scalpMode == SIM_SCALP_BONES) {
    from = skinned(guide, 0u);
    to = skinned(guide, frame.boneCount);
  } else {
    from = frame.headFrom;
    to = frame.headTo;
  }
}

// The hair grid at world point p (docs/THEORY.md §2.7): flow = (density x velocity, density), pressure =
// (its head-space gradient, pressure), both trilinear.
void sampleGrid(vec3 p, mat4 headInverse, out vec4 flow, out vec4 pressure) {
  ivec3 cellBase;
  vec3 frac;
  gridFootprint((headInverse * vec4(p, 1.0)).xyz, frame.gridOriginCell, cellBase, frac);
  flow = vec4(0.0);
  pressure = vec4(0.0);
  for (uint k = 0u; k < 8u; ++k) {
    float w;
    int cell = gridCorner(cellBase, frac, frame.gridDims.xyz, k, w);
    if (cell < 0) continue;
    flow += w * grid[GRID_CELL_VEC4S * uint(cell)];
    pressure += w * grid[GRID_CELL_VEC4S * uint(cell) + 1u];
  }
}

// Strand interaction through the grid (docs/THEORY.md §2.7). Friction pulls the step v toward the hair's mean
// velocity around the particle. Where the hair is denser than the target, the particle is given an outward
// speed down the pressure gradient of at least volume (as a speed) x |gradient| x cell size, GRID_VOLUME_BLEND
// of the shortfall per substep: a velocity, not a force, so a grid one frame old does not make hair at rest
// ring, and in proportion to the gradient, so it fades where the pressure peaks instead of flipping there.
void gridInteraction(vec3 p, inout vec3 v, float h, mat4 headInverse) {
  vec4 flow, pressure;
  sampleGrid(p, headInverse, flow, pressure);
  if (flow.w > 1e-4) v = mix(v, flow.xyz * (h / flow.w), frame.gridForces.y);
  vec3 slope = transpose(mat3(headInverse)) * pressure.xyz;  // a gradient: by the inverse transpose
  float len = length(slope);
  if (pressure.w <= 0.0 || len < 1e-12) return;
  vec3 outward = -slope / len;
  float shortfall = frame.gridForces.x * len * frame.gridOriginCell.w * h - dot(v, outward);
  if (shortfall > 0.0) v += outward * (shortfall * GRID_VOLUME_BLEND);
}

void integrate(uint base, uint n, mat4 root, vec3 accel, float h, mat4 headInverse) {
  x[0] = transformPoint(root, rest[base].xyz);  // the root is pinned to the scalp
  xPrev[0] = x[0];
  float maxStep = frame.maxSpeed * h;
  bool gridActs = frame.gridDims.w != 0u;
  for (uint i = 1u; i < n; ++i) {
    vec3 v = (x[i] - xPrev[i]) * (1.0 - frame.damping);
    if (gridActs) gridInteraction(x[i], v, h, headInverse);
    float speed = length(v);
    if (speed > maxStep) v *= maxStep / speed;
    xPrev[i] = x[i];
    x[i] += v + accel * (h * h);
  }
}

void pullTowardRest(uint base, uint n, mat4 head) {
  float k = frame.stiffness;
  for (uint i = 1u; i < n && k > 0.0; ++i) {
    x[i] += k * (transformPoint(head, rest[base + i].xyz) - x[i]);
    k *= frame.stiffnessFalloff;
  }
}

// The rotation taking unit a onto unit b along the shortest arc (identity when they are opposite).
mat3 rotationBetween(vec3 a, vec3 b) {
  vec3 v = cross(a, b);
  float c = dot(a, b);
  if (c < -0.9999) return mat3(1.0);
  mat3 vx = mat3(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0);  // vx * w = cross(v, w)
  return mat3(1.0) + vx + vx * vx / (1.0 + c);
}

// Local shape (docs/THEORY.md §2.6), root to tip: segment i moves frame.localStiffness of the way to its rest
// segment turned by the frame its parent segment carries now, the correction split between its two ends (the
// root's child alone moves), like the length constraints'. The frame starts as the
// root's and follows each segment as it lies after the move, by the shortest rotation from where the frame
// expected it, so bends are kept relative to the strand itself, not to the head.
void keepLocalShape(uint base, uint n, mat4 root) {
  float k = frame.localStiffness;
  mat3 carried = mat3(root);
  for (uint i = 1u; i < n; ++i) {
    vec3 expected = carried * (rest[base + i].xyz - rest[base + i - 1u].xyz);
    vec3 delta = k * (x[i - 1u] + expected - x[i]);
    if (i == 1u) {
      x[i] += delta;  // the root does not move
    } else {
      x[i - 1u] -= 0.5 * delta;
      x[i] += 0.5 * delta;
    }
    vec3 now = x[i] - x[i - 1u];
    float le = length(expected), ln = length(now);
    if (le > 1e-12 && ln > 1e-12) carried = rotationBetween(expected / le, now / ln) * carried;
  }
}

// One Gauss-Seidel sweep, root to tip. `leaderOnly` moves only the child of each segment
// (follow-the-leader): after such a sweep every segment has exactly its rest length.
void satisfyLengths(uint base, uint n, bool leaderOnly) {
  for (uint i = 1u; i < n; ++i) {
    vec3 d = x[i] - x[i - 1u];
    float len = length(d);
    if (len < 1e-12) continue;
    vec3 correction = d * ((len - rest[base + i].w) / len);
    if (i == 1u || leaderOnly) {
      x[i] -= correction;  // the root does not move
    } else {
      x[i - 1u] += 0.5 * correction;
      x[i] -= 0.5 * correction;
    }
  }
}

// Where a pearl inside a collider goes: onto the collider surface (docs/THEORY.md §2.4). Of the surface
// points, it takes the one at the segment's rest length from its parent that is nearest to it (the
// two spheres meet in a circle), so a strand lying on the head keeps its length; where the spheres
// do not meet it falls back to the paper's radial push.
vec3 resolvePearl(vec3 p, vec3 parent, float restLength, vec3 center, float reach) {
  vec3 fromCenter = p - center;
  float dist = length(fromCenter);
  vec3 radial = center + (dist > 1e-12 ? fromCenter / dist : vec3(0.0, 1.0, 0.0)) * reach;
  vec3 axis = parent - center;
  float d = length(axis);
  if (d < 1e-12 || d + reach < restLength || abs(d - reach) > restLength) return radial;
  axis /= d;
  float along = (d * d + reach * reach - restLength * restLength) / (2.0 * d);
  float ringRadius = sqrt(max(reach * reach - along * along, 0.0));
  vec3 inPlane = fromCenter - dot(fromCenter, axis) * axis;
  float inPlaneLength = length(inPlane);
  if (inPlaneLength < 1e-12) return radial;
  return center + along * axis + (ringRadius / inPlaneLength) * inPlane;
}

// Colliders overlap (cranium, face, neck, shoulders): leaving one can enter another, so the colliders
// are visited again, up to SIM_COLLISION_PASSES times, while the last visit moved a pearl.
// A capsule acts on a pearl as the sphere around the nearest point of its axis.
vec3 nearestOnSegment(vec3 p, vec3 a, vec3 b) {
  vec3 ab = b - a;
  float len2 = dot(ab, ab);
  float t = len2 > 1e-20 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

void collide(uint base, uint n, mat4 head) {
  bool moved = true;
  for (uint pass = 0u; pass < SIM_COLLISION_PASSES && moved; ++pass) {
    moved = false;
    for (uint c = 0u; c < frame.colliderCount; ++c) {
      vec3 center = transformPoint(head, frame.colliders[c].xyz);
      float reach = frame.colliders[c].w + frame.pearlRadius;
      for (uint i = 1u; i < n; ++i) {
        if (length(x[i] - center) >= reach) continue;
        x[i] = resolvePearl(x[i], x[i - 1u], rest[base + i].w, center, reach);
        moved = true;
      }
    }
    for (uint c = 0u; c < frame.capsuleCount; ++c) {
      vec3 a = transformPoint(head, frame.capsules[2u * c].xyz);
      vec3 b = transformPoint(head, frame.capsules[2u * c + 1u].xyz);
      float reach = frame.capsules[2u * c].w + frame.pearlRadius;
      for (uint i = 1u; i < n; ++i) {
        vec3 center = nearestOnSegment(x[i], a, b);
        if (length(x[i] - center) >= reach) continue;
        x[i] = resolvePearl(x[i], x[i - 1u], rest[base + i].w, center, reach);
        moved = true;
      }
    }
  }
}

// The distance-grid collider after the spheres: the grid is the head's own surface.
void collideSdf(uint n, mat4 head, mat4 headInverse) {
  for (uint i = 1u; i < n; ++i) x[i] = sdfKeepOutside(x[i], head, headInverse, frame.pearlRadius);
}

void main() {
  uint guide = hpThreadId(SIM_WORKGROUP_SIZE);
  if (guide >= frame.guideCount) return;
  const uint n = PARTICLES;
  uint base = guide * n;
  for (uint i = 0u; i < n; ++i) {
    x[i] = positions[base + i].xyz;
    xPrev[i] = previous[base + i].xyz;
  }
  mat4 rootFrom, rootTo;
  rootMatrices(guide, base, rootFrom, rootTo);
  if (frame.teleport != 0u) {
    mat4 carry = rootTo * inverse(rootFrom);
    for (uint i = 0u; i < n; ++i) {
      x[i] = transformPoint(carry, x[i]);
      xPrev[i] = transformPoint(carry, xPrev[i]);
    }
  }
  float h = frame.gravity.w;
  float phase = gustPhase(guide);
  for (uint s = 0u; s < frame.substeps; ++s) {
    float t = float(s + 1u) / float(frame.substeps);
    mat4 head = frame.teleport != 0u ? frame.headTo : frame.headFrom * (1.0 - t) + frame.headTo * t;
    mat4 root = frame.teleport != 0u ? rootTo : rootFrom * (1.0 - t) + rootTo * t;
    float gust = 1.0 + frame.wind.w * sin(6.28318530718 * frame.gustFrequency * (frame.time + h * float(s + 1u)) + phase);
    vec3 accel = frame.gravity.xyz + frame.wind.xyz * gust;
    mat4 headInverse = inverse(head);
    integrate(base, n, root, accel, h, headInverse);
    pullTowardRest(base, n, root);
    for (uint it = 0u; it < frame.iterations; ++it) {
      if (frame.localStiffness > 0.0) keepLocalShape(base, n, root);
      // Symmetric sweeps converge slowly for a chain hanging from a pinned root; the last sweep is
      // follow-the-leader so lengths are exact before the final collision push.
      satisfyLengths(base, n, it + 1u == frame.iterations);
      collide(base, n, head);
      collideSdf(n, head, headInverse);
    }
  }
  for (uint i = 0u; i < n; ++i) {
    positions[base + i] = vec4(x[i], 1.0);
    previous[base + i] = vec4(xPrev[i], 1.0);
  }
}
