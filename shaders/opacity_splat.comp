#version 460
// Opacity maps in compute (shared/opacity.h, docs/THEORY.md §5): one invocation per strand segment of a
// chunk. It rasterizes the segment as seen from the light by the graphics pass's rule (strict lines: the
// texel centres inside the 1-texel-wide rectangle along the segment), takes the slice coordinate s and
// the opacity at each centre's projection onto the segment (perspective-correct, as the graphics pass
// interpolates them), and adds the opacity in fixed point to the texel's bin of the first slice at or
// behind s: one atomic per fragment where the graphics pass blends 16 slices; opacity_resolve.glsl makes
// the sums cumulative. A spot's segments are clipped at its plane (w > 0) like the graphics pass's;
// texels outside the map are skipped; a segment with a non-finite end adds nothing. Deep opacity maps run it
// once (OPACITY_SPLAT_MODE_DEEP_FINE) or, where their fine bins do not fit, twice: OPACITY_SPLAT_MODE_FIRST,
// then _DEEP (shared/opacity.h).
#include "shared/opacity.h"
#include "common.glsl"
#include "opacity_footprint.glsl"

layout(local_size_x = OPACITY_SPLAT_WORKGROUP_SIZE) in;
// 1: the first-hair step reads a texel before its atomic minimum (GPUs); 0: the atomic alone (CPU devices).
layout(constant_id = 0) const uint READ_BEFORE_MIN = 1u;
// OPACITY_SPLAT_MODE_*: one pipeline per mode, so the others' code is left out (lavapipe would run it under a mask).
layout(constant_id = 1) const uint MODE = OPACITY_SPLAT_MODE_PLAIN;
layout(std430, binding = OPACITY_SPLAT_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = OPACITY_SPLAT_BINDING_LIGHT) readonly buffer Light { LightSpace lights[]; };
layout(std430, binding = OPACITY_SPLAT_BINDING_BINS) buffer Bins { uint bins[]; };
layout(std430, binding = OPACITY_SPLAT_BINDING_FIRST) buffer First { uint first[]; };
layout(push_constant) uniform Push { OpacitySplatPush push; };

const float MIN_W = 1.0e-6;

// A segment end in texels (x right, y down, centres at +0.5) with 1/w, s/w and opacity/w, so attributes
// interpolate perspective-correctly along the line.
struct End {
  vec2 texel;
  float invW, sOverW, opacityOverW;
};

End endOf(vec4 clip, float opacity) {
  End e;
  e.invW = 1.0 / clip.w;
  e.texel = vec2(0.5 + 0.5 * clip.x * e.invW, 0.5 - 0.5 * clip.y * e.invW) * float(push.resolution);
  e.sOverW = clip.z * float(OPACITY_SLICES) * e.invW;
  e.opacityOverW = opacity * e.invW;
  return e;
}

// Adds a fragment like opacity.frag: to every slice i >= s - epsilon, i.e. to the bin of the first one.
// Deep maps in two splats: step 1 only keeps the texel's nearest s (every fragment step 2 will see: s0
// always exists); step 2 measures s from it, OPACITY_DEEP_FACTOR finer, and the last slice takes everything
// farther (its layer reaches to infinity, as Yuksel & Keyser's last layer does). In one splat: the nearest s
// and the fine bin of s, one deep slice wide, over the whole depth range (the resolve places the slices).
void addFragment(ivec2 texel, float s, float opacity) {
  uint at = uint(texel.y) * push.resolution + uint(texel.x);
  if (MODE == OPACITY_SPLAT_MODE_FIRST || MODE == OPACITY_SPLAT_MODE_DEEP_FINE) {
    // The texel's value only falls, so a read (even a stale one) at or below this s means the atomic would
    // change nothing: dense hair's later fragments skip it (fewer atomics on the same texels).
    uint nearest = orderedFromFloat(clamp(s, 0.0, float(OPACITY_SLICES)));
    if (READ_BEFORE_MIN == 0u || first[at] > nearest) atomicMin(first[at], nearest);
    if (MODE == OPACITY_SPLAT_MODE_FIRST) return;
  }
  uint index;
  if (MODE == OPACITY_SPLAT_MODE_DEEP_FINE) {
    if (!(opacity > 0.0)) return;
    float fine = s * OPACITY_DEEP_FACTOR;  // the last bin also takes anything farther; NaN: the first
    index = opacityFineBin(at, fine > 0.0 ? min(uint(fine), OPACITY_DEEP_BINS - 1u) : 0u);
  } else {
    if (MODE == OPACITY_SPLAT_MODE_DEEP)
      s = min((s - floatFromOrdered(first[at])) * OPACITY_DEEP_FACTOR, float(OPACITY_SLICES));
    float behind = s - OPACITY_SLICE_EPSILON;
    if (!(behind <= float(OPACITY_SLICES)) || !(opacity > 0.0)) return;  // past the last slice, or nothing
    index = at * OPACITY_SLICES + uint(max(ceil(behind), 1.0)) - 1u;
  }
  // One add is at most OPACITY_MAX_FRAGMENT_FIXED (alpha 256: T = 0 already), so a bin past the saturation
  // bit, which takes each later add back, could only wrap with 128 such adds in flight at once.
  uint value = uint(min(opacity * OPACITY_FIXED_ONE + 0.5, float(OPACITY_MAX_FRAGMENT_FIXED)));
  if (value == 0u) return;
  if ((atomicAdd(bins[index], value) & OPACITY_BIN_SATURATED) != 0u) atomicAdd(bins[index], -value);
}

// First and last index (inclusive) of the texel centres k + 0.5 in [lo, hi), clamped to the map; none
// for NaN bounds.
ivec2 centresIn(float lo, float hi) {
  if (!(lo <= hi)) return ivec2(0, -1);
  float n = float(push.resolution);
  return ivec2(clamp(ceil(lo - 0.5), 0.0, n), clamp(ceil(hi - 0.5), 0.0, n) - 1.0);
}

// A segment's 1-texel-wide rectangle in the frame of its major axis u (x or y of the map): its start, its
// direction and what each column's test takes.
struct Rectangle {
  bool xMajor;
  vec2 start, dir;
  float len2, halfV, slope, invDirY;
};

// The rows (minor-axis texel centres) of column i: within half the width over cos of the line, cut by the ends
// (0 <= (p - a).d < |d|^2) and the map. At most 2; none past an end.
ivec2 rowsOf(Rectangle r, int i) {
  float du = float(i) + 0.5 - r.start.x;
  float line = r.start.y + du * r.slope;
  float lo = line - r.halfV, hi = line + r.halfV;
  if (r.dir.y != 0.0) {
    float v0 = r.start.y - du * r.dir.x * r.invDirY, v1 = r.start.y + (r.len2 - du * r.dir.x) * r.invDirY;
    lo = max(lo, min(v0, v1));
    hi = min(hi, max(v0, v1));
  } else if (!(du * r.dir.x >= 0.0 && du * r.dir.x < r.len2)) {
    return ivec2(0, -1);
  }
  return centresIn(lo, hi);
}

// Walks the major axis u, column by column, one fragment per iteration: the lanes of a SIMD vector (8 on
// lavapipe) each take their own segment's next fragment, so the vector runs as many iterations as its
// longest segment has fragments rather than, per column, as many as the column with most rows.
void splat(End a, End b) {
  vec2 d = b.texel - a.texel;
  float len2 = dot(d, d);
  if (!(len2 > 1.0e-12 && len2 < 1.0e30)) return;  // a point, or not finite
  Rectangle r;
  r.xMajor = abs(d.x) >= abs(d.y);
  r.start = r.xMajor ? a.texel : a.texel.yx;
  r.dir = r.xMajor ? d : d.yx;
  r.len2 = len2;
  float len = sqrt(len2), invLen2 = 1.0 / len2;
  r.halfV = 0.5 * len / abs(r.dir.x);
  float padU = 0.5 * abs(r.dir.y) / len;
  // Per segment, not per column: lavapipe does not turn a division by a loop invariant into a product.
  r.slope = r.dir.y / r.dir.x;
  r.invDirY = r.dir.y != 0.0 ? 1.0 / r.dir.y : 0.0;
  ivec2 columns = centresIn(min(r.start.x, r.start.x + r.dir.x) - padU, max(r.start.x, r.start.x + r.dir.x) + padU);
  int i = columns.x;
  ivec2 rows = rowsOf(r, i);
  int j = rows.x;
  while (i <= columns.y) {
    if (j <= rows.y) {  // an empty column (past an end, off the map) only moves on
      ivec2 texel = r.xMajor ? ivec2(i, j) : ivec2(j, i);
      float t = clamp(dot(vec2(texel) + 0.5 - a.texel, d) * invLen2, 0.0, 1.0);
      float w = 1.0 / mix(a.invW, b.invW, t);
      addFragment(texel, mix(a.sOverW, b.sOverW, t) * w, mix(a.opacityOverW, b.opacityOverW, t) * w);
    }
    if (j < rows.y) {
      ++j;
    } else {
      rows = rowsOf(r, ++i);
      j = rows.x;
    }
  }
}

// Liang-Barsky against one plane, inside where the distance is >= 0 (d0, d1 at the ends): narrows the
// parameter range t; false when nothing is left (or a distance is not finite).
bool clipTo(float d0, float d1, inout vec2 t) {
  if (!(d0 == d0) || !(d1 == d1)) return false;
  if (d0 < 0.0 && d1 < 0.0) return false;
  if (d0 < 0.0) t.x = max(t.x, d0 / (d0 - d1));
  else if (d1 < 0.0) t.y = min(t.y, d0 / (d0 - d1));
  return t.x <= t.y;
}

void main() {
  uint segment = hpThreadId(OPACITY_SPLAT_WORKGROUP_SIZE);
  if (segment >= push.segmentCount) return;
  uint q = push.verticesPerStrand;
  uint k = segment % (q - 1u);
  uint v = (segment / (q - 1u)) * q + k;
  LightSpace light = lights[push.slot];
  vec4 c0 = light.viewProj * vec4(positions[v].xyz, 1.0);
  vec4 c1 = light.viewProj * vec4(positions[v + 1u].xyz, 1.0);
  float o0 = strandFragmentOpacity(light, push.footprint, push.opacity, float(k) / float(q - 1u), c0.w);
  float o1 = strandFragmentOpacity(light, push.footprint, push.opacity, float(k + 1u) / float(q - 1u), c1.w);
  // Clip in clip space (attributes linear there, as the graphics clipper does) to the spot's plane and to
  // the map's frustum, with a margin, so projected ends stay within a few map widths (float precision).
  vec2 t = vec2(0.0, 1.0);
  if (!clipTo(c0.w - MIN_W, c1.w - MIN_W, t)) return;
  const float reach = 1.5;
  if (!clipTo(reach * c0.w - c0.x, reach * c1.w - c1.x, t) || !clipTo(reach * c0.w + c0.x, reach * c1.w + c1.x, t) ||
      !clipTo(reach * c0.w - c0.y, reach * c1.w - c1.y, t) || !clipTo(reach * c0.w + c0.y, reach * c1.w + c1.y, t))
    return;
  vec4 a = mix(c0, c1, t.x), b = mix(c0, c1, t.y);
  splat(endOf(a, mix(o0, o1, t.x)), endOf(b, mix(o0, o1, t.y)));
}
