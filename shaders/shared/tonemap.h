// Shared by GLSL and C++: the display curve of the tonemap pass (shaders/tonemap.frag) and of the host
// tools that must produce the same PNG from linear radiance (`hairpipe reference`, image comparisons).
// Linear radiance x (already times the exposure) -> display value in [0, 1] before the sRGB transfer
// function: Narkowicz's fit of the ACES filmic curve, per channel.
#ifndef HP_SHARED_TONEMAP_H
#define HP_SHARED_TONEMAP_H
#include "common.h"

#ifdef __cplusplus
#include <algorithm>
#define HP_TONEMAP_FN inline
#define HP_TONEMAP_CLAMP(x) std::clamp(x, 0.0f, 1.0f)
#else
#define HP_TONEMAP_FN
#define HP_TONEMAP_CLAMP(x) clamp(x, 0.0, 1.0)
#endif

HP_BEGIN
HP_TONEMAP_FN float tonemapFilmic(float x) {
  return HP_TONEMAP_CLAMP((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f));
}
HP_END
#endif
