#version 460
// raster_fine.glsl, the direct walk (CPU devices), for a multisampled head depth (raster_head_depth.glsl).
#define RASTER_HEAD_MULTISAMPLED
#include "raster_fine.glsl"
