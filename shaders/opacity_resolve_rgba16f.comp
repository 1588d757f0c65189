#version 460
// The compute opacity resolve for RGBA16F maps (opacity_resolve.glsl).
#define OPACITY_MAPS_FORMAT rgba16f
#include "opacity_resolve.glsl"
