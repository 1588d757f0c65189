#version 460
// raster_shade.glsl for a single-sample head depth (raster_head_depth.glsl).
#include "raster_shade.glsl"
