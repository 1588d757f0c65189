#version 460
// raster_shade.glsl for a multisampled head depth (raster_head_depth.glsl).
#define RASTER_HEAD_MULTISAMPLED
#include "raster_shade.glsl"
