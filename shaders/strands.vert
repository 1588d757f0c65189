#version 460
// Camera-facing ribbons pulled from the render strand buffers (no vertex input). Quad k of a strand
// spans vertices k and k+1; the ribbon thins from the root to the tip. A ribbon narrower than a
// pixel is widened to one pixel and its coverage is passed on (the fragment shader turns it into a
// dithered sample mask with MSAA, alpha without), so thin
// hair stays smooth instead of breaking into dashes. The fragment shader looks the shadows up per light;
// the skin's bounce comes per vertex from the strand's samples (bounce_samples.glsl).
#include "shared/render.h"
#include "shared/strands.h"

layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Tangents { vec4 tangents[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Attributes { StrandAttributes attributes[]; };
layout(std430, binding = RENDER_BINDING_BOUNCE_SAMPLES) readonly buffer BounceSamples { uvec2 bounceSamples[]; };
layout(push_constant) uniform Push { StrandDrawPush push; };
#include "bounce_samples.glsl"

layout(location = 0) out vec3 outWorld;
layout(location = 1) out vec3 outTangent;
layout(location = 2) out float outCoverage;
layout(location = 3) out float outColorScale;
layout(location = 4) flat out uint outStrand;  // global strand index: keys the coverage dither
layout(location = 5) out vec3 outBounce;       // the skin's bounce at this end of the segment
layout(location = 6) flat out float outRandom; // the strand's random value: keys its tilt (strandTilt)

void main() {
  uint q = frame.options.x;
  uint perSegment = push.lines != 0u ? STRAND_VERTICES_PER_LINE : STRAND_VERTICES_PER_QUAD;
  uint segment = gl_VertexIndex / perSegment;
  uint corner = gl_VertexIndex % perSegment;
  uint strand = segment / (q - 1u);
  uint k = segment % (q - 1u);
  // Quad corners (triangles 0-1-2, 3-4-5): which end of the segment, which side of the ribbon.
  bool farEnd = push.lines != 0u ? corner == 1u : (corner == 2u || corner == 3u || corner == 5u);
  float side = (corner == 1u || corner == 4u || corner == 5u) ? 1.0 : -1.0;
  uint v = strand * q + k + (farEnd ? 1u : 0u);

  vec3 p = positions[v].xyz;
  float along = positions[v].w;
  vec3 t = normalize(tangents[v].xyz);
  StrandAttributes attr = attributes[strand];
  vec3 toEye = frame.cameraPosition.xyz - p;
  float width = frame.strand.x * attr.widthScale * mix(1.0, frame.strand.y, along);
  float viewDepth = max(-(frame.view * vec4(p, 1.0)).z, 1e-4);
  float pixel = frame.cameraPosition.w * viewDepth;
  float coverage = min(width / pixel, 1.0);
  if (push.lines == 0u) {
    vec3 sideDir = cross(t, toEye);
    float len = length(sideDir);
    sideDir = len > 1e-12 ? sideDir / len : vec3(0.0);
    p += sideDir * (0.5 * max(width, pixel) * side);
  }
  outWorld = p;
  outTangent = t;
  outCoverage = coverage;
  outColorScale = attr.colorScale;
  outRandom = attr.random;
  outStrand = push.firstStrand + strand;
  outBounce = bounceAlongStrand(strand, v - strand * q, q);
  gl_Position = frame.proj * frame.view * vec4(p, 1.0);
}
