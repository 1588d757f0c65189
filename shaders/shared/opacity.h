// Shared by GLSL and C++: opacity shadow maps (docs/THEORY.md §5): the bounds pass
// (compute/shadows/bounds_pass.h, shaders/bounds.comp), the opacity pass (compute/shadows/opacity_pass.h,
// shaders/opacity*.vert/.frag) and the lookup in the shading passes (shaders/public/hairpipe/hair_shadows.glsl, also installed for applications; included below).
//
// Light space. For a directional light with unit direction L (from the hair toward the light), the
// host builds an orthonormal basis (rows r0, r1, r2 = L; see lightBasis in bounds_pass.cpp): a point p
// has light coordinates x = r0.p, y = r1.p and depth d = -L.p (growing away from the light). The
// bounds pass reduces [x, y, d] over every render strand vertex and builds an orthographic
// viewProj: clip.xy in [-1, 1] over the padded x/y box, clip.z = (d - z_near) / (z_far - z_near), so
// the continuous slice coordinate of a point is s = OPACITY_SLICES * clip.z and slice i
// (i = 1..16) sits at s = i, i.e. depth z_i = z_near + i d_z.
//
// Opacity maps: one 2D-array image of OPACITY_TARGETS layers, RGBA; slice i is layer (i-1)/4,
// channel (i-1)%4, and holds alpha(z_i) = sum of the per-fragment opacities at s <= i.
//
// Shadow slots: every shadowed light of a frame (up to OPACITY_MAX_LIGHTS) has a slot s with its own
// LightSpace (element s of the light-space buffer), its own OPACITY_LAYERS layers of the maps' image from
// layer s x OPACITY_LAYERS, and its own layer s of the heads' depth map. The passes take the slot in their
// push constants; the shading passes loop over the frame's lights (RenderFrame, shared/render.h).
#ifndef HP_SHARED_OPACITY_H
#define HP_SHARED_OPACITY_H
#include "common.h"
// The maps' layout an application's shaders read too (installed as <hairpipe/hair_shadows.glsl>): the
// constants below take its values, and GLSL includers get its lookup functions.
#include "../public/hairpipe/hair_shadows.glsl"

HP_BEGIN
HP_CONST(uint, OPACITY_SLICES, HAIRPIPE_SHADOW_SLICES)
HP_CONST(uint, OPACITY_TARGETS, HAIRPIPE_SHADOW_SLICE_LAYERS)  // RGBA layers of slices: OPACITY_SLICES / 4
// The image has one layer more: deep opacity maps (OpacitySettings::deep) keep each texel's first hair
// there, as its global slice coordinate s0 in .x (OPACITY_NO_HAIR where none); the slices then start at s0
// and are OPACITY_DEEP_FACTOR times finer: deep slice coordinate = (s - s0) x OPACITY_DEEP_FACTOR.
HP_CONST(uint, OPACITY_LAYERS, HAIRPIPE_SHADOW_LAYERS)
HP_CONST(float, OPACITY_DEEP_FACTOR, HAIRPIPE_SHADOW_DEEP_FACTOR)
HP_CONST(float, OPACITY_NO_HAIR, HAIRPIPE_SHADOW_NO_HAIR)  // exact in RGBA16F too
// A fragment at slice coordinate s adds to slice i when s <= i + OPACITY_SLICE_EPSILON, so hair at
// exactly z_far (s = 16 up to rounding) still lands in slice 16.
HP_CONST(float, OPACITY_SLICE_EPSILON, 1.0e-3f)
HP_CONST(uint, OPACITY_MAX_LIGHTS, 4)  // shadow slots (RendererSettings::shadowedLights at most)

// Bounds pass (compute): per chunk a reduction, then one finalize dispatch.
HP_CONST(uint, BOUNDS_WORKGROUP_SIZE, 256)
HP_CONST(uint, BOUNDS_VERTICES_PER_THREAD, 8)
HP_CONST(uint, BOUNDS_BINDING_POSITIONS, 0)   // vec4[chunk strands * Q] render strand positions
HP_CONST(uint, BOUNDS_BINDING_LIGHT, 1)       // LightSpace[slots] (read-modify-write: the push's slot)
HP_CONST(uint, BOUNDS_MODE_REDUCE, 0)
HP_CONST(uint, BOUNDS_MODE_FINALIZE, 1)

// Opacity pass (graphics): strands as lines, the head as triangles.
HP_CONST(uint, OPACITY_BINDING_POSITIONS, 0)  // strands: vec4[chunk strands * Q]; head: vec4 positions
HP_CONST(uint, OPACITY_BINDING_INDICES, 1)    // head only: uint indices (triangle list)
HP_CONST(uint, OPACITY_BINDING_LIGHT, 2)      // LightSpace[slots] (read: the push's slot)

// Opacity pass (compute, OpacityRaster::Compute): each segment's fragments (the texel centres inside the
// 1-texel-wide rectangle along it: the strict-line rule of the graphics pass) add their opacity in fixed
// point to ONE bin per texel, the first slice at or behind them; the resolve turns the 16 bins of a texel
// into the cumulative alpha(z_i) of the graphics pass and writes the maps. Bins: uint[res * res * 16],
// texel-major (texel (x, y) row y from the top, then slice); deep maps in one splat: OPACITY_DEEP_BINS per
// texel, laid out by opacityFineBin (below).
HP_CONST(uint, OPACITY_SPLAT_WORKGROUP_SIZE, 64)
HP_CONST(uint, OPACITY_RESOLVE_WORKGROUP_SIZE, 64)
HP_CONST(uint, OPACITY_SPLAT_BINDING_POSITIONS, 0)  // vec4[chunk strands * Q] render strand positions
HP_CONST(uint, OPACITY_SPLAT_BINDING_LIGHT, 1)      // LightSpace[slots] (read: the push's slot)
HP_CONST(uint, OPACITY_SPLAT_BINDING_BINS, 2)       // uint bins (atomic adds)
HP_CONST(uint, OPACITY_SPLAT_BINDING_FIRST, 3)      // uint[res * res]: each texel's first hair (atomicMin, ordered s)
HP_CONST(uint, OPACITY_SPLAT_MODE_PLAIN, 0)         // bins of the global slices
HP_CONST(uint, OPACITY_SPLAT_MODE_FIRST, 1)         // deep maps, step 1: only the first hair per texel
HP_CONST(uint, OPACITY_SPLAT_MODE_DEEP, 2)          // deep maps, step 2: bins of the slices from the first hair
// Deep maps in one splat (where OPACITY_DEEP_BINS bins per texel fit the device): each fragment lowers its
// texel's first hair and adds to one of OPACITY_DEEP_BINS fine bins of the global depth range (fine bin j:
// slice coordinates [j, j + 1) / OPACITY_DEEP_FACTOR, one deep slice wide); the resolve places the deep
// slices from the first hair over them (opacity_resolve.glsl).
HP_CONST(uint, OPACITY_SPLAT_MODE_DEEP_FINE, 3)
HP_CONST(uint, OPACITY_DEEP_BINS, 64)               // OPACITY_SLICES x OPACITY_DEEP_FACTOR
HP_CONST(uint, OPACITY_RESOLVE_BINDING_BINS, 0)     // uint bins (read)
HP_CONST(uint, OPACITY_RESOLVE_BINDING_MAPS, 1)     // the maps as a storage image2DArray (written)
HP_CONST(uint, OPACITY_RESOLVE_BINDING_FIRST, 2)    // the first-hair buffer (read; deep maps)
HP_CONST(uint, OPACITY_RESOLVE_GLOBAL, 0)           // 16 bins per texel: global slices
HP_CONST(uint, OPACITY_RESOLVE_DEEP, 1)             // 16 bins per texel from the first hair (two splats)
HP_CONST(uint, OPACITY_RESOLVE_DEEP_FINE, 2)        // OPACITY_DEEP_BINS fine bins per texel (one splat)
// Fixed point: a bin holds opacity x 2^16 (a fragment of 0.04 rounds by < 2e-4 of itself). A bin that
// reaches OPACITY_BIN_SATURATED (alpha 32768: T = 0 for any k >= 0.003) takes no more adds and resolves
// to OPACITY_SATURATED_ALPHA, so an absurd pile-up saturates instead of wrapping around.
HP_CONST(float, OPACITY_FIXED_ONE, 65536.0f)
HP_CONST(uint, OPACITY_BIN_SATURATED, 0x80000000u)
HP_CONST(float, OPACITY_SATURATED_ALPHA, 32768.0f)
HP_CONST(float, OPACITY_MAX_FRAGMENT_FIXED, 16777216.0f)  // 2^24: one fragment adds at most alpha 256

// Light-space framing, written on the device by the bounds pass and read by every later pass.
struct LightSpace {
  mat4 viewProj;      // world -> light clip (orthographic, or perspective for a spot); see the header comment
  vec4 depthRange;    // x = z_near, y = z_far (light depth d = -L.p), z = d_z = (z_far - z_near) / 16, w = 1 / d_z
  vec4 extent;        // x, y = min light x, y; z, w = max light x, y (padded box the map covers; spot: x/d, y/d)
  uvec4 minBits;      // reduction accumulators: order-preserving uint encodings (orderedFromFloat) of
  uvec4 maxBits;      // min / max of (x, y, d); the finalize step re-arms them for the next frame
};

struct BoundsPush {
  vec4 row0;          // light basis rows (world -> light x, y), w = 0
  vec4 row1;
  vec4 row2;          // = L; light depth d = -dot(row2.xyz, p)
  uint vertexCount;   // vertices in this chunk (reduce)
  uint mode;          // BOUNDS_MODE_*
  float marginWorld;  // x/y padding added on each side (half the widest strand), scene units
  float marginTexels; // extra x/y padding in texels of the opacity map
  uint resolution;    // opacity map size (texels per side)
  uint perspective;   // 1: spot light (perspective framing from `origin`), 0: directional
  float tanCone;      // spot: tan of the cone half-angle, caps the angular box
  float nearLimit;    // spot: vertices with d <= nearLimit (at or behind the spot) are left out
  vec4 origin;        // spot: xyz = world position of the spot, w = 0; directional: 0
  uint slot;          // the light's shadow slot: which LightSpace of the buffer
  uint pad0;
  uint pad1;
  uint pad2;
};

struct OpacityPush {
  mat4 headToWorld;   // head draws only
  float opacity;      // head: added per fragment; strands: see footprint.w
  uint verticesPerStrand;  // strands: Q
  uint slot;               // the light's shadow slot: which LightSpace of the buffer
  uint pad1;
  // Strands: x = width at the root (scene units), y = tip width / root width, z = 1 / map resolution,
  // w = 1: a fragment adds opacity x width / texel size (the fraction of the texel the strand covers
  // per texel of its length: Beer-Lambert alpha = covered area / texel area); w = 0: adds `opacity`.
  vec4 footprint;
};
struct OpacitySplatPush {
  vec4 footprint;          // as OpacityPush::footprint
  float opacity;           // as OpacityPush::opacity (strands)
  uint verticesPerStrand;  // Q
  uint segmentCount;       // segments in this chunk: strands x (Q - 1)
  uint resolution;         // map texels per side
  uint slot;               // the light's shadow slot: which LightSpace of the buffer
  uint pad0;
  uint pad1;
  uint pad2;
};

struct OpacityResolvePush {
  uint resolution;         // map texels per side
  uint pad0;
};
HP_END

// Order-preserving float <-> uint: a < b (floats, no NaN) iff encode(a) < encode(b) (uints), so
// atomicMin/atomicMax on the encodings reduce floats.
#ifdef __cplusplus
#include <bit>
namespace hp::gpu {
inline std::uint32_t orderedFromFloat(float f) {
  std::uint32_t u = std::bit_cast<std::uint32_t>(f);
  return (u & 0x80000000u) ? ~u : (u | 0x80000000u);
}
inline float floatFromOrdered(std::uint32_t u) {
  return std::bit_cast<float>((u & 0x80000000u) ? (u & 0x7fffffffu) : ~u);
}
}  // namespace hp::gpu
#else
uint orderedFromFloat(float f) {
  uint u = floatBitsToUint(f);
  return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}
float floatFromOrdered(uint u) {
  return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u);
}
#endif

// Where fine bin `bin` of texel `texel` lies in the bins (OpacityBins::DeepFine): in groups of
// OPACITY_FINE_GROUP texels along a row, bin by bin, so one segment's neighbouring fragments at about the
// same depth add to the same few cache lines, and one texel's bins lie in one small block.
HP_BEGIN
HP_CONST(uint, OPACITY_FINE_GROUP, 16)
#ifdef __cplusplus
constexpr
#endif
uint opacityFineBin(uint texel, uint bin) {
  return (texel / OPACITY_FINE_GROUP) * (OPACITY_FINE_GROUP * OPACITY_DEEP_BINS) + bin * OPACITY_FINE_GROUP +
         texel % OPACITY_FINE_GROUP;
}
HP_END

#ifdef __cplusplus
#include <cstddef>
static_assert(hp::gpu::OPACITY_SLICES == 4 * hp::gpu::OPACITY_TARGETS);
static_assert(float(hp::gpu::OPACITY_DEEP_BINS) == float(hp::gpu::OPACITY_SLICES) * hp::gpu::OPACITY_DEEP_FACTOR);
static_assert(sizeof(hp::gpu::LightSpace) == 128);
static_assert(offsetof(hp::gpu::LightSpace, depthRange) == 64);
static_assert(offsetof(hp::gpu::LightSpace, minBits) == 96);
static_assert(sizeof(hp::gpu::BoundsPush) == 112);
static_assert(offsetof(hp::gpu::BoundsPush, origin) == 80);
static_assert(offsetof(hp::gpu::BoundsPush, vertexCount) == 48);
static_assert(sizeof(hp::gpu::OpacityPush) == 96);
static_assert(offsetof(hp::gpu::OpacityPush, footprint) == 80);
static_assert(offsetof(hp::gpu::OpacityPush, opacity) == 64);
static_assert(sizeof(hp::gpu::OpacitySplatPush) == 48);
static_assert(sizeof(hp::gpu::OpacityResolvePush) == 8);
#endif
#endif
