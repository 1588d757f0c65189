#version 460
// Writes the hair's motion into the application's velocity attachment, at colour location VELOCITY_LOCATION
// (compiled once per location, shaders/CMakeLists.txt), inside the rendering recordComposite draws in: where
// the hair's coverage exceeds minCoverage, motion * scale + offset; elsewhere the fragment is discarded and the
// attachment keeps what it holds. The coverage is the alpha the composite leaves in the pixel: over several
// samples, the near layer's in the near mask's share of them and the far layer's in the rest (composite.frag).
// The pipeline writes only that attachment's first two channels, in every sample of the pixel.
#include "shared/raster.h"

layout(binding = COMPOSITE_BINDING_HAIR) uniform sampler2D hair;
layout(binding = COMPOSITE_BINDING_NEAR) uniform sampler2D nearHair;
layout(binding = COMPOSITE_BINDING_NEAR_MASK) uniform usampler2D nearMask;
layout(binding = COMPOSITE_BINDING_MOTION) uniform sampler2D motion;
layout(push_constant) uniform Push { CompositeVelocityPush push; };
layout(location = VELOCITY_LOCATION) out vec4 outVelocity;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float coverage = texelFetch(hair, pixel, 0).a;
  if (push.samples > 1u) {
    float nearShare = float(bitCount(texelFetch(nearMask, pixel, 0).r)) / float(push.samples);
    coverage = mix(coverage, texelFetch(nearHair, pixel, 0).a, nearShare);
  }
  if (!(coverage > push.minCoverage)) discard;
  outVelocity = vec4(texelFetch(motion, pixel, 0).xy * push.scale + push.offset, 0.0, 0.0);
}
