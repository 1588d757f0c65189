#version 460
// raster_fine.glsl, the staged walk (GPUs), for a single-sample head depth (raster_head_depth.glsl).
#define RASTER_FINE_STAGED
#include "raster_fine.glsl"
