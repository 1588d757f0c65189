#version 460
// The compute opacity resolve for RGBA32F maps (opacity_resolve.glsl).
#define OPACITY_MAPS_FORMAT rgba32f
#include "opacity_resolve.glsl"
