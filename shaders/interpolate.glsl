// Interpolation (docs/THEORY.md §1.4): render strand s of a scalp triangle with guides A, B, C and
// barycentrics X is K_j = X1 A_j + X2 B_j + X3 C_j for every vertex j of the smoothed guides.
// Tangents: the guides' unit tangents blended with the same weights and renormalised (A's tangent if
// the blend vanishes). Also writes the strand's attributes (makeStrandAttributes, shared/strands.h).
// Debug mode INTERPOLATE_MODE_GUIDES: strand s is smoothed guide firstStrand + s, copied as is.
// Three walks (compute/strands/interpolate_pass.h InterpolateWalk): per strand and per vertex in
// interpolate.comp (specialization constant WALK), staged in interpolate_staged.comp (its own shader, so the
// others declare no shared memory):
// - per strand (CPU devices): one invocation per strand of one chunk, looping over its Q vertices; the
//   binding and triangle are read once per strand (1.65x faster on lavapipe than one invocation per vertex,
//   docs/PERFORMANCE.md), but a warp's lanes write Q*16 bytes apart.
// - per vertex (GPUs, plain blend): one invocation per vertex, so a warp's stores are contiguous; the
//   strand's binding and triangle are re-read by its Q lanes from cache.
// - staged (GPUs, groom detail, whose frame is carried along the strand): the per-strand walk in blocks of
//   INTERPOLATE_STAGE_VERTICES vertices kept in shared memory, which the workgroup then writes out strand
//   after strand, so a warp's stores are contiguous runs. The same arithmetic as per strand (a compiler may
//   contract it differently in the two shaders: last-bit differences).
#include "shared/strands.h"
#include "common.glsl"

layout(local_size_x = INTERPOLATE_WORKGROUP_SIZE) in;
#ifndef INTERPOLATE_STAGED
layout(constant_id = 0) const uint WALK = INTERPOLATE_WALK_STRAND;  // INTERPOLATE_WALK_STRAND or _VERTEX
#endif
layout(std430, binding = INTERPOLATE_BINDING_GUIDE_POSITIONS) readonly buffer GuidePositions { vec4 guidePositions[]; };
layout(std430, binding = INTERPOLATE_BINDING_GUIDE_TANGENTS) readonly buffer GuideTangents { vec4 guideTangents[]; };
layout(std430, binding = INTERPOLATE_BINDING_TRIANGLES) readonly buffer Triangles { uvec4 triangles[]; };
layout(std430, binding = INTERPOLATE_BINDING_BINDINGS) readonly buffer Bindings { StrandBindingGpu bindings[]; };
layout(std430, binding = INTERPOLATE_BINDING_POSITIONS) writeonly buffer Positions { vec4 positions[]; };
layout(std430, binding = INTERPOLATE_BINDING_TANGENTS) writeonly buffer Tangents { vec4 tangents[]; };
layout(std430, binding = INTERPOLATE_BINDING_ATTRIBUTES) writeonly buffer Attributes { StrandAttributes attributes[]; };
layout(push_constant) uniform Push { InterpolatePush push; };

#ifdef INTERPOLATE_STAGED
// The staged walk's block: row l (the workgroup's strand l) holds its vertices stageStart + k at slot k and
// its tangents stageStart - 1 + k at slot k (they run one vertex behind).
shared vec4 stagedPositions[INTERPOLATE_WORKGROUP_SIZE * INTERPOLATE_STAGE_ROW];
shared vec4 stagedTangents[INTERPOLATE_WORKGROUP_SIZE * INTERPOLATE_STAGE_ROW];
uint stageStart = 0u;

// The groomed walk's stores go to the workgroup's block.
void putPosition(uint dst, uint j, vec4 p) {
  stagedPositions[gl_LocalInvocationID.x * INTERPOLATE_STAGE_ROW + j - stageStart] = p;
}
void putTangent(uint dst, uint j, vec4 t) {
  stagedTangents[gl_LocalInvocationID.x * INTERPOLATE_STAGE_ROW + j + 1u - stageStart] = t;
}
#else
// The groomed walk's stores go to the chunk.
void putPosition(uint dst, uint j, vec4 p) { positions[dst + j] = p; }
void putTangent(uint dst, uint j, vec4 t) { tangents[dst + j] = t; }
#endif

void copyGuide(uint s) {
  uint guide = push.firstStrand + s;
  uint src = guide * push.vertices, dst = s * push.vertices;
  for (uint j = 0u; j < push.vertices; ++j) {
    positions[dst + j] = guidePositions[src + j];
    tangents[dst + j] = guideTangents[src + j];
  }
  attributes[s] = makeStrandAttributes(strandHash01(guide, 0u), guide);
}

// Groom detail (push.groom, shared/strands.h GroomParams; docs/THEORY.md "Groom detail"). Clumping pulls the
// strand toward its clump centre: the nearest (in barycentrics) of push.groom.clump.x points hashed in its
// scalp triangle, blended from the same guides. Curl winds it around that centreline on a helix of the
// curl radius, in a frame carried along the centreline by projection; frizz adds smooth value noise across
// it, growing as v^2 and toward the hairline (GroomParams.frizz.zw). Both ramp in over GROOM_ROOT_RAMP of v
// and key their per-strand values on the strand's random value, so a strand's shape is the same in every
// frame and run.
vec3 unitOr(vec3 d, vec3 fallback) {
  float len2 = dot(d, d);
  return len2 > 1e-30 ? d * inversesqrt(len2) : fallback;
}

bool groomOn() { return push.groom.clump.x >= 1.0 || push.groom.curl.x > 0.0 || push.groom.frizz.x > 0.0; }

vec3 blendAt(uvec3 src, vec3 w, uint j) {
  return w.x * guidePositions[src.x + j].xyz + w.y * guidePositions[src.y + j].xyz + w.z * guidePositions[src.z + j].xyz;
}

// The barycentrics of the clump centre nearest to w among the triangle's hashed centres.
vec3 clumpCentre(vec3 w, uint triangle) {
  uint count = uint(push.groom.clump.x);
  vec3 best = w;
  float bestDist = 1e30;
  for (uint k = 0u; k < count; ++k) {
    uint key = triangle * 64u + k;
    vec2 u = vec2(strandHash01(key, GROOM_STREAM_CLUMP), strandHash01(key, GROOM_STREAM_CLUMP + 1u));
    if (u.x + u.y > 1.0) u = 1.0 - u;  // uniform over the triangle
    vec3 c = vec3(u, 1.0 - u.x - u.y);
    float d = dot(c - w, c - w);
    if (d < bestDist) bestDist = d, best = c;
  }
  return best;
}

// Smooth value noise in [-1, 1] along x, one independent stream per (key, axis): the key is hashed before
// the cell is added, so neither neighbouring keys nor the two axes share shifted copies of one stream.
float groomNoise(uint key, uint axis, float x) {
  float i = floor(x), f = x - i;
  uint cell = strandHash(key * 2u + axis) + uint(int(i) + 65536);
  float a = strandHash01(cell, GROOM_STREAM_FRIZZ), b = strandHash01(cell + 1u, GROOM_STREAM_FRIZZ);
  return mix(a, b, f * f * (3.0 - 2.0 * f)) * 2.0 - 1.0;
}

// The strand's centreline (guides blended, clumped) at vertex j, and its v.
vec4 centreline(uvec3 src, vec3 w, vec3 centre, uint j) {
  float v = guidePositions[src.x + j].w;
  vec3 p = blendAt(src, w, j);
  if (push.groom.clump.x >= 1.0) p = mix(p, blendAt(src, centre, j), push.groom.clump.y * pow(v, push.groom.clump.z));
  return vec4(p, v);
}

// One groomed strand's walk: its fixed values and the state carried from vertex to vertex.
struct GroomWalk {
  uvec3 src;
  vec3 w, centre;
  uint key, dst;
  float radius, turns, phase, amplitude;
  vec4 c;             // the centreline at the last vertex, v in w
  vec3 t, n;          // its tangent and the normal carried along
  float along;        // arc length so far
  vec3 before, here;  // the last two vertices written
};

GroomWalk groomStart(uint s, StrandBindingGpu b, uvec3 src, vec3 w) {
  GroomWalk g;
  g.src = src;
  g.w = w;
  g.dst = s * push.vertices;
  g.key = strandKey(b.random);
  g.centre = push.groom.clump.x >= 1.0 ? clumpCentre(w, b.triangle) : w;
  float vary = push.groom.curl.z;
  g.radius = push.groom.curl.x * (1.0 + vary * (strandHash01(g.key, GROOM_STREAM_CURL) - 0.5));
  g.turns = push.groom.curl.y * (1.0 + vary * (strandHash01(g.key, GROOM_STREAM_CURL + 1u) - 0.5));
  g.phase = 6.2831853 * strandHash01(g.key, GROOM_STREAM_CURL + 2u);
  // Frizz by region: more toward the hairline (the triangle's distance from it in triangles[].w).
  float hairline = uintBitsToFloat(triangles[b.triangle].w);
  g.amplitude = push.groom.frizz.x * (1.0 + push.groom.frizz.z * exp(-hairline / push.groom.frizz.w));
  g.c = centreline(src, w, g.centre, 0u);
  g.t = normalize(guideTangents[src.x].xyz);
  // A normal to the root tangent, then carried along: projected onto each new tangent's normal plane.
  g.n = abs(g.t.y) < 0.9 ? normalize(cross(g.t, vec3(0.0, 1.0, 0.0))) : normalize(cross(g.t, vec3(1.0, 0.0, 0.0)));
  g.along = 0.0;
  g.before = vec3(0.0);
  g.here = vec3(0.0);
  return g;
}

// Vertex j (in order from 0) of the walk: its position, and the tangent of vertex j - 1 (and of j at the tip).
void groomStep(inout GroomWalk g, uint j) {
  if (j > 0u) {
    vec4 next = centreline(g.src, g.w, g.centre, j);
    vec3 step = next.xyz - g.c.xyz;
    float len = length(step);
    if (len > 1e-12) g.t = step / len;
    g.along += len;
    g.c = next;
    vec3 projected = g.n - dot(g.n, g.t) * g.t;
    if (dot(projected, projected) > 1e-12) g.n = normalize(projected);
  }
  vec3 m = cross(g.t, g.n);
  float ramp = smoothstep(0.0, GROOM_ROOT_RAMP, g.c.w);
  float angle = g.phase + 6.2831853 * g.turns * g.along;
  vec3 p = g.c.xyz + ramp * g.radius * (cos(angle) * g.n + sin(angle) * m);
  float frizz = g.amplitude * g.c.w * g.c.w;
  if (frizz > 0.0) {
    float x = push.groom.frizz.y * g.along;
    p += ramp * frizz * (groomNoise(g.key, 0u, x) * g.n + groomNoise(g.key, 1u, x) * m);
  }
  putPosition(g.dst, j, vec4(p, g.c.w));
  // Tangents by central differences, one vertex behind (one-sided at the ends).
  if (j >= 1u) {
    vec3 d = j >= 2u ? p - g.before : p - g.here;
    putTangent(g.dst, j - 1u, vec4(unitOr(d, g.t), 0.0));
  }
  if (j + 1u == push.vertices) putTangent(g.dst, j, vec4(unitOr(p - g.here, g.t), 0.0));
  g.before = g.here;
  g.here = p;
}

void interpolateGroomed(uint s, StrandBindingGpu b, uvec3 src, vec3 w) {
  GroomWalk g = groomStart(s, b, src, w);
  for (uint j = 0u; j < push.vertices; ++j) groomStep(g, j);
  attributes[s] = makeStrandAttributes(b.random, b.triangle);
}

// Vertex j of the plain blend of the guides `src` with weights w, at dst.
void blendVertex(uvec3 src, vec3 w, uint j, uint dst) {
  vec3 ta = guideTangents[src.x + j].xyz;
  vec3 tan = unitOr(w.x * ta + w.y * guideTangents[src.y + j].xyz + w.z * guideTangents[src.z + j].xyz, ta);
  positions[dst] = vec4(blendAt(src, w, j), guidePositions[src.x + j].w);  // w = v, the same for all guides
  tangents[dst] = vec4(tan, 0.0);
}

vec3 bindingWeights(StrandBindingGpu b) { return vec3(b.x1, b.x2, max(0.0, 1.0 - b.x1 - b.x2)); }

void interpolate(uint s) {
  StrandBindingGpu b = bindings[s];
  uvec3 src = triangles[b.triangle].xyz * push.vertices;
  vec3 w = bindingWeights(b);
  if (groomOn()) {
    interpolateGroomed(s, b, src, w);
    return;
  }
  for (uint j = 0u; j < push.vertices; ++j) blendVertex(src, w, j, s * push.vertices + j);
  attributes[s] = makeStrandAttributes(b.random, b.triangle);
}

// The per-vertex walk: vertex i of the chunk (plain blend only: the pass stages groomed chunks and keeps
// guides-only chunks on the per-strand walk).
void interpolateVertex(uint i) {
  uint s = i / push.vertices, j = i % push.vertices;
  StrandBindingGpu b = bindings[s];
  blendVertex(triangles[b.triangle].xyz * push.vertices, bindingWeights(b), j, i);
  if (j == 0u) attributes[s] = makeStrandAttributes(b.random, b.triangle);
}

#ifdef INTERPOLATE_STAGED
// Writes the block of vertices j0 .. j0 + n - 1 of the workgroup's `count` strands from `first` on, and
// their tangents from vertex j0 - 1 (none before the root) through j0 + n - 2 (through the tip in the last
// block), strand after strand: consecutive lanes, consecutive addresses.
void writeStage(uint first, uint count, uint j0, uint n) {
  uint q = push.vertices;
  for (uint e = gl_LocalInvocationID.x; e < count * n; e += INTERPOLATE_WORKGROUP_SIZE) {
    uint row = e / n, k = e % n;
    positions[(first + row) * q + j0 + k] = stagedPositions[row * INTERPOLATE_STAGE_ROW + k];
  }
  uint from = max(j0, 1u) - 1u, to = j0 + n == q ? q - 1u : j0 + n - 2u;
  uint m = to + 1u - from, slot = from + 1u - j0;
  for (uint e = gl_LocalInvocationID.x; e < count * m; e += INTERPOLATE_WORKGROUP_SIZE) {
    uint row = e / m, k = e % m;
    tangents[(first + row) * q + from + k] = stagedTangents[row * INTERPOLATE_STAGE_ROW + slot + k];
  }
}

// The staged walk (groomed strands): each lane walks its strand a block at a time; the barriers are in
// uniform control flow (a workgroup past the chunk leaves as a whole).
void interpolateStaged(uint id) {
  uint first = id - gl_LocalInvocationID.x;
  if (first >= push.strandCount) return;
  uint count = min(INTERPOLATE_WORKGROUP_SIZE, push.strandCount - first);
  bool mine = gl_LocalInvocationID.x < count;
  GroomWalk g;
  if (mine) {
    StrandBindingGpu b = bindings[id];
    g = groomStart(id, b, triangles[b.triangle].xyz * push.vertices, bindingWeights(b));
    attributes[id] = makeStrandAttributes(b.random, b.triangle);
  }
  for (uint j0 = 0u; j0 < push.vertices; j0 += INTERPOLATE_STAGE_VERTICES) {
    stageStart = j0;
    uint n = min(INTERPOLATE_STAGE_VERTICES, push.vertices - j0);
    if (mine)
      for (uint j = j0; j < j0 + n; ++j) groomStep(g, j);
    barrier();
    writeStage(first, count, j0, n);
    barrier();  // the block is read before the next one overwrites it
  }
}
#endif

void main() {
  uint id = hpThreadId(INTERPOLATE_WORKGROUP_SIZE);
#ifdef INTERPOLATE_STAGED
  interpolateStaged(id);
#else
  if (WALK == INTERPOLATE_WALK_VERTEX) {
    if (id < push.strandCount * push.vertices) interpolateVertex(id);
    return;
  }
  if (id >= push.strandCount) return;
  if (push.mode == INTERPOLATE_MODE_GUIDES)
    copyGuide(id);
  else
    interpolate(id);
#endif
}
