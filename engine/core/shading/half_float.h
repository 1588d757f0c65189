#pragma once
// Contract: IEEE 754 binary16 conversion, round-to-nearest-even, with subnormals, infinities and NaN.
// roundToHalf(x) returns the float the GPU will see after storing x in an RGBA16F texel, so the CPU
// emulation of the LUT measures the format's quantisation too.
#include <cstdint>

namespace hp::shading {
std::uint16_t floatToHalf(float x);
float halfToFloat(std::uint16_t h);
inline float roundToHalf(float x) { return halfToFloat(floatToHalf(x)); }
}  // namespace hp::shading
