#version 460
// Composites the compute rasterizer's hair image (premultiplied radiance, alpha = 1 - T) over the
// attachment: the pipeline blends with ONE, ONE_MINUS_SRC_ALPHA. One fetch per pixel, no filtering; pixels
// without hair (all zero) are discarded, the blend leaving them unchanged anyway. Over
// a multisampled attachment it is drawn twice (shared/raster.h COMPOSITE_*): the far layer into the
// samples outside the pixel's near mask, then the near layer into the samples inside it.
#include "shared/raster.h"

layout(binding = COMPOSITE_BINDING_HAIR) uniform sampler2D hair;
layout(binding = COMPOSITE_BINDING_NEAR) uniform sampler2D nearHair;
layout(binding = COMPOSITE_BINDING_NEAR_MASK) uniform usampler2D nearMask;
layout(push_constant) uniform Layer { uint samples; } layer;
layout(location = 0) out vec4 outColor;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  // Written on every path: a shader that writes the sample mask anywhere leaves it undefined where it does not.
  if (layer.samples == COMPOSITE_EVERY_SAMPLE) {
    gl_SampleMask[0] = ~0;
    outColor = texelFetch(hair, pixel, 0);
  } else {
    uint mask = texelFetch(nearMask, pixel, 0).r;
    bool near = layer.samples == COMPOSITE_NEAR_SAMPLES;
    if (near && mask == 0u) discard;
    gl_SampleMask[0] = int(near ? mask : ~mask);
    outColor = near ? texelFetch(nearHair, pixel, 0) : texelFetch(hair, pixel, 0);
  }
  // No hair: the blend (ONE, ONE_MINUS_SRC_ALPHA) would leave the attachment as it is, so skip its samples'
  // read-modify-write (most of the screen; GPUs with few raster units pay per blended sample).
  if (outColor == vec4(0.0)) discard;
}
