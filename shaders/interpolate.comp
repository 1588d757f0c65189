#version 460
// interpolate.glsl: the per-strand and per-vertex walks (specialization constant 0).
#include "interpolate.glsl"
