#version 460
// raster_fine.glsl, the direct walk (CPU devices), for a single-sample head depth (raster_head_depth.glsl).
#include "raster_fine.glsl"
