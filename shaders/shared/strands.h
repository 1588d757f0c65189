// Shared by GLSL and C++: the render-strand data of the tessellate and interpolate passes
// (compute/strands/tessellate_pass.h, compute/strands/interpolate_pass.h, compute/strands/strand_buffers.h). One source of
// truth for bindings, workgroup sizes, push constants, the per-strand structs, the sample
// distribution along a strand and the per-strand attribute hash.
//
// Buffers (all std430, tightly packed arrays; G guides, P particles, Q vertices, S render strands):
//   guide particles  vec4[G*P]  xyz position, w unused; root first (the simulation's output)
//   smoothed guides  vec4[G*Q]  positions: xyz, w = v (0 at the root, 1 at the tip)
//                    vec4[G*Q]  tangents: xyz unit (root to tip), w = 0
//   triangles        uvec4[T]   x, y, z = guides A, B, C; w = render strands in the triangle
//   bindings         StrandBindingGpu[S]
//   strand positions vec4[S*Q]  as smoothed guides: xyz, w = v
//   strand tangents  vec4[S*Q]  xyz unit, w = 0
//   attributes       StrandAttributes[S]
// Vertex j of strand s is element s*Q + j. Per-strand arrays are split into chunks when they would
// exceed maxStorageBufferRange; within a chunk, s is the chunk-local strand index.
// Dispatch: tessellate has one invocation per smoothed vertex (G*Q); interpolate one per strand of a
// chunk looping over its Q vertices (per strand and staged walks), or one per vertex of a chunk (per
// vertex walk). All use hpThreadId(WORKGROUP_SIZE) and bounds-check.
#ifndef HP_SHARED_STRANDS_H
#define HP_SHARED_STRANDS_H
#include "common.h"

// Functions defined once for both languages (plain arithmetic only).
#ifdef __cplusplus
#include <cstddef>
#define HP_STRANDS_FN inline constexpr
#else
#define HP_STRANDS_FN
#endif

HP_BEGIN
HP_CONST(uint, TESSELLATE_WORKGROUP_SIZE, 64)
HP_CONST(uint, TESSELLATE_BINDING_PARTICLES, 0)  // in:  vec4[G*P] guide particles
HP_CONST(uint, TESSELLATE_BINDING_POSITIONS, 1)  // out: vec4[G*Q] smoothed guide positions
HP_CONST(uint, TESSELLATE_BINDING_TANGENTS, 2)   // out: vec4[G*Q] smoothed guide tangents

HP_CONST(uint, INTERPOLATE_WORKGROUP_SIZE, 64)
HP_CONST(uint, INTERPOLATE_BINDING_GUIDE_POSITIONS, 0)  // in:  vec4[G*Q]
HP_CONST(uint, INTERPOLATE_BINDING_GUIDE_TANGENTS, 1)   // in:  vec4[G*Q]
HP_CONST(uint, INTERPOLATE_BINDING_TRIANGLES, 2)        // in:  uvec4[T]: guides, w = hairline distance bits
HP_CONST(uint, INTERPOLATE_BINDING_BINDINGS, 3)         // in:  StrandBindingGpu[chunk strands]
HP_CONST(uint, INTERPOLATE_BINDING_POSITIONS, 4)        // out: vec4[chunk strands * Q]
HP_CONST(uint, INTERPOLATE_BINDING_TANGENTS, 5)         // out: vec4[chunk strands * Q]
HP_CONST(uint, INTERPOLATE_BINDING_ATTRIBUTES, 6)       // out: StrandAttributes[chunk strands]

// The walks (interpolate.comp's specialization constant 0, and interpolate_staged.comp;
// compute/strands/interpolate_pass.h InterpolateWalk).
HP_CONST(uint, INTERPOLATE_WALK_STRAND, 0)  // one invocation per strand, its stores Q x 16 bytes apart
HP_CONST(uint, INTERPOLATE_WALK_VERTEX, 1)  // plain blend: one invocation per vertex
HP_CONST(uint, INTERPOLATE_WALK_STAGED, 2)  // groom: per strand, stores staged in blocks for the workgroup
// The staged walk's block: each strand's next INTERPOLATE_STAGE_VERTICES vertices go to shared memory (a row
// of INTERPOLATE_STAGE_VERTICES + 1 slots per strand: the tangents run one vertex behind), then the workgroup
// writes them out strand after strand.
HP_CONST(uint, INTERPOLATE_STAGE_VERTICES, 12)
HP_CONST(uint, INTERPOLATE_STAGE_ROW, INTERPOLATE_STAGE_VERTICES + 1u)  // vec4 slots per strand and block

HP_CONST(uint, INTERPOLATE_MODE_STRANDS, 0)  // K_j = X1 A_j + X2 B_j + X3 C_j per binding
HP_CONST(uint, INTERPOLATE_MODE_GUIDES, 1)   // debug: render strand s is smoothed guide s

HP_CONST(uint, MAX_VERTICES_PER_STRAND, 256)
// Groom detail (GroomParams): curl and frizz grow from 0 at the root to full over this much of v, so the
// roots stay where they are bound; the hash streams of a strand's curl and frizz values.
HP_CONST(float, GROOM_ROOT_RAMP, 0.15f)
HP_CONST(uint, GROOM_STREAM_CLUMP, 16u)
HP_CONST(uint, GROOM_STREAM_CURL, 32u)
HP_CONST(uint, GROOM_STREAM_FRIZZ, 48u)

// Attribute ranges: widthScale in [WIDTH_SCALE_MIN, WIDTH_SCALE_MAX), colorScale likewise.
HP_CONST(float, WIDTH_SCALE_MIN, 0.75f)
HP_CONST(float, WIDTH_SCALE_MAX, 1.25f)
HP_CONST(float, COLOR_SCALE_MIN, 0.8f)
HP_CONST(float, COLOR_SCALE_MAX, 1.2f)

struct TessellatePush {
  uint guideCount;
  uint particles;  // P
  uint vertices;   // Q
  uint pad;
};

// Groom detail of the interpolated strands (hp::GroomSettings, engine/core/hair/groom.h; interpolate.glsl):
// all zero leaves every strand the plain blend of its guides.
struct GroomParams {
  vec4 clump;  // x = clump centres per scalp triangle (0: none), y = pull toward the centre at the tip,
               // z = profile exponent (pull = y v^z along v in [0, 1]), w = 0
  vec4 curl;   // x = radius (scene units), y = turns per scene unit of length, z = per-strand variation
               // [0, 1], w = 0
  vec4 frizz;  // x = amplitude at the tip (scene units; v^2 from the root), y = cycles per scene unit,
               // z = the amplitude's extra factor at the hairline, w = its fall-off distance (scene units)
};

struct InterpolatePush {
  uint firstStrand;  // global index of the chunk's first strand (guides mode: first guide)
  uint strandCount;  // strands in this chunk
  uint vertices;     // Q
  uint mode;         // INTERPOLATE_MODE_*
  GroomParams groom;
};

// One render strand: barycentrics of guides A and B (C gets max(0, 1 - x1 - x2)), the asset's
// per-strand random value in [0, 1) and the triangle index.
struct StrandBindingGpu {
  float x1;
  float x2;
  float random;
  uint triangle;
};

// Per-strand shading attributes, written by the interpolate pass.
struct StrandAttributes {
  float random;      // StrandBinding::random (guides mode: strandHash01(guide, 0))
  float widthScale;  // multiplies the strand width
  float colorScale;  // multiplies the base colour (lightness variation)
  uint source;       // triangle index (guides mode: guide index)
};

// PCG integer hash (Jarzynski & Olano 2020), same constants as hp::pcgHash in engine/core/hair/rng.h.
HP_STRANDS_FN uint strandHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Uniform in [0, 1) from a key and a stream; the top 24 bits, exact in float.
HP_STRANDS_FN float strandHash01(uint key, uint stream) {
  return float(strandHash(strandHash(key) + stream) >> 8u) * (1.0f / 16777216.0f);
}

// A strand's random value r in [0, 1) as a hash key: r is a multiple of 2^-24 (hashRandom), so
// uint(r * 2^24) recovers its 24 bits exactly.
HP_STRANDS_FN uint strandKey(float random) { return uint(random * 16777216.0f); }

// Attributes of a strand from its random value: its key (strandKey) keys two further independent hashes.
HP_STRANDS_FN StrandAttributes makeStrandAttributes(float random, uint source) {
  uint key = strandKey(random);
  StrandAttributes a;
  a.random = random;
  a.widthScale = WIDTH_SCALE_MIN + (WIDTH_SCALE_MAX - WIDTH_SCALE_MIN) * strandHash01(key, 1u);
  a.colorScale = COLOR_SCALE_MIN + (COLOR_SCALE_MAX - COLOR_SCALE_MIN) * strandHash01(key, 2u);
  a.source = source;
  return a;
}

// A strand's cuticle tilt offset (radians), added to the material's alpha_R in its shading: uniform in
// [-variation, variation) (MarschnerParams.caustic.z, hp::HairMaterial::tiltVariation), from the strand's key
// on its own hash stream; the frame export writes each strand's value for the reference.
HP_CONST(uint, STRAND_STREAM_TILT, 3u)
HP_STRANDS_FN float strandTilt(float random, float variation) {
  return variation * (2.0f * strandHash01(strandKey(random), STRAND_STREAM_TILT) - 1.0f);
}

// A strand's longitudinal roughness scale, multiplying the material's beta_R in its shading (every lobe's
// width: v_TT and v_TRT follow v_R): one of STRAND_ROUGHNESS_LEVELS values evenly spaced over [1 - variation,
// 1 + variation], each as likely (MarschnerParams.caustic.w, hp::HairMaterial::roughnessVariation), on its own
// hash stream. A level each because the physical M texture holds a layer per level (shared/marschner.h), which
// a strand reads exactly; the frame export writes each strand's value.
HP_CONST(uint, STRAND_STREAM_ROUGHNESS, 4u)
HP_CONST(uint, STRAND_ROUGHNESS_LEVELS, 7u)
HP_STRANDS_FN uint strandRoughnessLevel(float random) {
  uint level = uint(strandHash01(strandKey(random), STRAND_STREAM_ROUGHNESS) * float(STRAND_ROUGHNESS_LEVELS));
  return level < STRAND_ROUGHNESS_LEVELS ? level : STRAND_ROUGHNESS_LEVELS - 1u;
}
HP_STRANDS_FN float strandRoughnessOfLevel(uint level, float variation) {
  return 1.0f + variation * (2.0f * float(level) / float(STRAND_ROUGHNESS_LEVELS - 1u) - 1.0f);
}
HP_STRANDS_FN float strandRoughness(float random, float variation) {
  return strandRoughnessOfLevel(strandRoughnessLevel(random), variation);
}

// Sample distribution along a strand (Q vertices over the P - 1 Bezier segments). Particle i sits
// exactly at vertex particleVertex(i) = round(i (Q-1) / (P-1)), so every particle is hit and the
// Q - 1 intervals are spread as evenly as integers allow (P=7, Q=36: particles at vertices
// 0 6 12 18 23 29 35, segments of 6 6 6 5 6 6 intervals). Vertex j of segment i has the Bezier
// parameter u = (j - particleVertex(i)) / (particleVertex(i+1) - particleVertex(i)).
// The same distribution for every guide, so vertex j of the three guides of a triangle correspond.
// Requires 2 <= P <= Q.
HP_STRANDS_FN uint particleVertex(uint i, uint particles, uint vertices) {
  uint segments = particles - 1u;
  return (2u * i * (vertices - 1u) + segments) / (2u * segments);
}

// The segment (0 .. P-2) holding vertex j: the last i with particleVertex(i) <= j, capped at P-2.
HP_STRANDS_FN uint vertexSegment(uint j, uint particles, uint vertices) {
  uint segments = particles - 1u;
  uint i = (j * segments) / (vertices - 1u);  // particleVertex(i) <= j; one step may remain
  if (i >= segments) i = segments - 1u;
  if (i + 1u < segments && particleVertex(i + 1u, particles, vertices) <= j) i = i + 1u;
  return i;
}
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::TessellatePush) == 16);
static_assert(sizeof(hp::gpu::InterpolatePush) == 64);
static_assert(sizeof(hp::gpu::StrandBindingGpu) == 16);
static_assert(offsetof(hp::gpu::StrandBindingGpu, random) == 8);
static_assert(offsetof(hp::gpu::StrandBindingGpu, triangle) == 12);
static_assert(sizeof(hp::gpu::StrandAttributes) == 16);
static_assert(offsetof(hp::gpu::StrandAttributes, widthScale) == 4);
static_assert(offsetof(hp::gpu::StrandAttributes, colorScale) == 8);
static_assert(offsetof(hp::gpu::StrandAttributes, source) == 12);
static_assert(hp::gpu::particleVertex(3, 7, 36) == 18 && hp::gpu::particleVertex(4, 7, 36) == 23);
static_assert(hp::gpu::vertexSegment(35, 7, 36) == 5 && hp::gpu::vertexSegment(23, 7, 36) == 4);
#endif
#endif
