#version 460
// raster_tile_depth.glsl for a single-sample head depth (raster_head_depth.glsl).
#include "raster_tile_depth.glsl"
