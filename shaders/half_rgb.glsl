// An rgb value in two uints as half floats (packHalf2x16: rg, then b and 0), GLSL only: the compute raster's
// vertex colours (shared/raster.h RASTER_BINDING_COLORS) and the skin's bounce samples along the strands
// (shared/render.h RENDER_BINDING_BOUNCE_SAMPLES). Usable in every stage.
#ifndef HP_HALF_RGB_GLSL
#define HP_HALF_RGB_GLSL

uvec2 packHalfRgb(vec3 c) { return uvec2(packHalf2x16(c.rg), packHalf2x16(vec2(c.b, 0.0))); }

vec3 unpackHalfRgb(uvec2 v) { return vec3(unpackHalf2x16(v.x), unpackHalf2x16(v.y).x); }
#endif
