#version 460
// Opacity maps in compute (shared/opacity.h, REFERENCES.md §4): one invocation per strand segment of a
// chunk. It rasterizes the segment as seen from the light by the graphics pass's rule (strict lines: the
// texel centres inside the 1-texel-wide rectangle along the segment), takes the slice coordinate s and
// the opacity at each centre's projection onto the segment (perspective-correct, as the graphics pass
// interpolates them), and adds the opacity in fixed point to the texel's bin of the first slice at or
// behind s: one atomic per fragment where the graphics pass blends 16 slices; opacity_resolve.glsl makes
// the sums cumulative. A spot's segments are clipped at its plane (w > 0) like the graphics pass's;
// texels outside the map are skipped; a segment with a non-finite end adds nothing. Deep opacity maps run it
// twice: OPACITY_SPLAT_MODE_FIRST, then _DEEP (shared/opacity.h).
#include "shared/opacity.h"
#include "common.glsl"
#include "opacity_footprint.glsl"

layout(local_size_x = OPACITY_SPLAT_WORKGROUP_SIZE) in;
layout(std430, binding = OPACITY_SPLAT_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = OPACITY_SPLAT_BINDING_LIGHT) readonly buffer Light { LightSpace light; };
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
// Deep maps: step 1 only keeps the texel's nearest s; step 2 measures s from it, OPACITY_DEEP_FACTOR finer.
void addFragment(ivec2 texel, float s, float opacity) {
  uint at = uint(texel.y) * push.resolution + uint(texel.x);
  if (push.mode == OPACITY_SPLAT_MODE_FIRST) {
    if (s >= 0.0 && s <= float(OPACITY_SLICES)) atomicMin(first[at], orderedFromFloat(s));
    return;
  }
  if (push.mode == OPACITY_SPLAT_MODE_DEEP) s = (s - floatFromOrdered(first[at])) * OPACITY_DEEP_FACTOR;
  float behind = s - OPACITY_SLICE_EPSILON;
  if (!(behind <= float(OPACITY_SLICES)) || !(opacity > 0.0)) return;  // past the last slice, or nothing
  uint slice = uint(max(ceil(behind), 1.0)) - 1u;
  uint value = uint(min(opacity * OPACITY_FIXED_ONE + 0.5, float(OPACITY_BIN_SATURATED)));
  uint index = at * OPACITY_SLICES + slice;
  if (value == 0u) return;
  // A bin already saturated takes the add back (rare), so it can never wrap around.
  if ((atomicAdd(bins[index], value) & OPACITY_BIN_SATURATED) != 0u) atomicAdd(bins[index], -value);
}

// First and last index (inclusive) of the texel centres k + 0.5 in [lo, hi), clamped to the map.
ivec2 centresIn(float lo, float hi) {
  float n = float(push.resolution);
  return ivec2(clamp(ceil(lo - 0.5), 0.0, n), clamp(ceil(hi - 0.5), 0.0, n) - 1.0);
}

// Walks the major axis u; at each column centre the rectangle spans |v - line(u)| <= half its width
// over cos, cut by the ends (0 <= (p - a).d < |d|^2). At most 2 texels per column.
void splat(End a, End b) {
  vec2 d = b.texel - a.texel;
  float len2 = dot(d, d);
  if (!(len2 > 1.0e-12 && len2 < 1.0e30)) return;  // a point, or not finite
  bool xMajor = abs(d.x) >= abs(d.y);
  vec2 start = xMajor ? a.texel : a.texel.yx;
  vec2 dir = xMajor ? d : d.yx;
  float len = sqrt(len2), invLen2 = 1.0 / len2;
  float halfV = 0.5 * len / abs(dir.x);
  float padU = 0.5 * abs(dir.y) / len;
  ivec2 columns = centresIn(min(start.x, start.x + dir.x) - padU, max(start.x, start.x + dir.x) + padU);
  for (int i = columns.x; i <= columns.y; ++i) {
    float du = float(i) + 0.5 - start.x;
    float line = start.y + du * dir.y / dir.x;
    float lo = line - halfV, hi = line + halfV;
    if (dir.y != 0.0) {
      float v0 = start.y - du * dir.x / dir.y, v1 = start.y + (len2 - du * dir.x) / dir.y;
      lo = max(lo, min(v0, v1));
      hi = min(hi, max(v0, v1));
    } else if (!(du * dir.x >= 0.0 && du * dir.x < len2)) {
      continue;
    }
    ivec2 rows = centresIn(lo, hi);
    for (int j = rows.x; j <= rows.y; ++j) {
      ivec2 texel = xMajor ? ivec2(i, j) : ivec2(j, i);
      float t = clamp(dot(vec2(texel) + 0.5 - a.texel, d) * invLen2, 0.0, 1.0);
      float w = 1.0 / mix(a.invW, b.invW, t);
      addFragment(texel, mix(a.sOverW, b.sOverW, t) * w, mix(a.opacityOverW, b.opacityOverW, t) * w);
    }
  }
}

void main() {
  uint segment = hpThreadId(OPACITY_SPLAT_WORKGROUP_SIZE);
  if (segment >= push.segmentCount) return;
  uint q = push.verticesPerStrand;
  uint k = segment % (q - 1u);
  uint v = (segment / (q - 1u)) * q + k;
  vec4 c0 = light.viewProj * vec4(positions[v].xyz, 1.0);
  vec4 c1 = light.viewProj * vec4(positions[v + 1u].xyz, 1.0);
  float o0 = strandFragmentOpacity(light, push.footprint, push.opacity, float(k) / float(q - 1u), c0.w);
  float o1 = strandFragmentOpacity(light, push.footprint, push.opacity, float(k + 1u) / float(q - 1u), c1.w);
  if (!(c0.w >= MIN_W) && !(c1.w >= MIN_W)) return;  // behind a spot (or not finite)
  if (!(c0.w >= MIN_W) || !(c1.w >= MIN_W)) {         // clip at the spot's plane, in clip space
    float t = (MIN_W - c0.w) / (c1.w - c0.w);
    vec4 c = mix(c0, c1, t);
    float o = mix(o0, o1, t);
    if (c0.w < MIN_W) {
      c0 = c;
      o0 = o;
    } else {
      c1 = c;
      o1 = o;
    }
  }
  splat(endOf(c0, o0), endOf(c1, o1));
}
