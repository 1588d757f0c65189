#version 460
// raster_fine.glsl, the staged walk (GPUs), for a multisampled head depth (raster_head_depth.glsl).
#define RASTER_FINE_STAGED
#define RASTER_HEAD_MULTISAMPLED
#include "raster_fine.glsl"
