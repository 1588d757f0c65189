// The head's depth as the compute rasterizer reads it: single-sample (sampler2D), or multisampled
// (sampler2DMS) where the including stage defines RASTER_HEAD_MULTISAMPLED. 1 where no head was drawn.
#ifdef RASTER_HEAD_MULTISAMPLED
layout(binding = RASTER_BINDING_DEPTH) uniform sampler2DMS headDepth;
uint headSamples() { return min(uint(textureSamples(headDepth)), RASTER_MAX_HEAD_SAMPLES); }
ivec2 headDepthSize() { return textureSize(headDepth); }
float headDepthAt(ivec2 pixel, uint s) { return texelFetch(headDepth, pixel, int(s)).r; }
#else
layout(binding = RASTER_BINDING_DEPTH) uniform sampler2D headDepth;
uint headSamples() { return 1u; }
ivec2 headDepthSize() { return textureSize(headDepth, 0); }
float headDepthAt(ivec2 pixel, uint s) { return texelFetch(headDepth, pixel, 0).r; }
#endif
