#pragma once
// Contract: helpers shared by the LUT builders: an empty RGBA texture of a given size and format, and
// a value rounded the way the GPU format stores it (RGBA16F: to the nearest half; RGBA32F: float).
#include <algorithm>

#include "engine/core/shading/half_float.h"
#include "engine/core/shading/lut.h"

namespace hp::shading {
// RGBA16F saturates at the largest half (65504) instead of rounding to infinity: a lobe far narrower than
// its texels (a tiny beta_R) peaks above it, and an infinite texel times a zero factor is NaN in a shader.
inline float quantiseTexel(double v, LutFormat f) {
  if (f != LutFormat::RGBA16F) return static_cast<float>(v);
  return roundToHalf(static_cast<float>(std::clamp(v, -65504.0, 65504.0)));
}

inline LutTexture makeLutTexture(const char* name, std::uint32_t w, std::uint32_t h, LutFormat f) {
  LutTexture t;
  t.name = name;
  t.width = w;
  t.height = h;
  t.format = f;
  t.data.assign(std::size_t(w) * h * 4, 0.0f);
  return t;
}
}  // namespace hp::shading
