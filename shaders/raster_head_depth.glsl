// The head's depth as the compute rasterizer reads it: single-sample (sampler2D), or multisampled
// (sampler2DMS) where the including stage defines RASTER_HEAD_MULTISAMPLED. 1 where no head was drawn, near
// below far: an application's reversed-Z depth (params.reversedDepth) is read as 1 - d, as raster_project.comp
// turns the hair's depth. The includer declares `params` (RasterParams) first.
#ifdef RASTER_HEAD_MULTISAMPLED
layout(binding = RASTER_BINDING_DEPTH) uniform sampler2DMS headDepth;
uint headSamples() { return min(uint(textureSamples(headDepth)), RASTER_MAX_HEAD_SAMPLES); }
ivec2 headDepthSize() { return textureSize(headDepth); }
float headDepthStored(ivec2 pixel, uint s) { return texelFetch(headDepth, pixel, int(s)).r; }
#else
layout(binding = RASTER_BINDING_DEPTH) uniform sampler2D headDepth;
uint headSamples() { return 1u; }
ivec2 headDepthSize() { return textureSize(headDepth, 0); }
float headDepthStored(ivec2 pixel, uint s) { return texelFetch(headDepth, pixel, 0).r; }
#endif
float headDepthAt(ivec2 pixel, uint s) {
  float d = headDepthStored(pixel, s);
  return params.reversedDepth != 0u ? 1.0 - d : d;
}
