#version 460
// Composites the compute rasterizer's hair image (premultiplied radiance, alpha = 1 - T) over the
// attachment: the pipeline blends with ONE, ONE_MINUS_SRC_ALPHA. One fetch per pixel, no filtering.
#include "shared/raster.h"

layout(binding = COMPOSITE_BINDING_HAIR) uniform sampler2D hair;
layout(location = 0) out vec4 outColor;

void main() { outColor = texelFetch(hair, ivec2(gl_FragCoord.xy), 0); }
