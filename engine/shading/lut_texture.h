#pragma once
// Contract: helpers shared by the LUT builders: an empty RGBA texture of a given size and format, and
// a value rounded the way the GPU format stores it (RGBA16F: to the nearest half; RGBA32F: float).
#include "engine/shading/half_float.h"
#include "engine/shading/lut.h"

namespace hp::shading {
inline float quantiseTexel(double v, LutFormat f) {
  float x = static_cast<float>(v);
  return f == LutFormat::RGBA16F ? roundToHalf(x) : x;
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
