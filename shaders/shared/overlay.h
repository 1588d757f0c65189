// Shared by GLSL and C++: the 2D overlay pass (a tool's UI, e.g. the viewer's Dear ImGui panel):
// textured, vertex-coloured triangles in pixel coordinates, pulled from a storage buffer.
#ifndef HP_SHARED_OVERLAY_H
#define HP_SHARED_OVERLAY_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, OVERLAY_BINDING_VERTICES, 0)  // storage buffer: OVERLAY_VERTEX_WORDS uints per vertex
HP_CONST(uint, OVERLAY_BINDING_TEXTURE, 1)   // combined image sampler: the font atlas (RGBA8 unorm)
// One vertex: pos.x, pos.y, uv.x, uv.y (floats) and an RGBA8 colour (sRGB-authored, packed R lowest).
HP_CONST(uint, OVERLAY_VERTEX_WORDS, 5)

// Pixel -> clip: clip = pos * scale + translate (clip y up: the pipelines' viewport is flipped).
struct OverlayPush {
  vec2 scale;
  vec2 translate;
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::OverlayPush) == 16);
#endif
#endif
