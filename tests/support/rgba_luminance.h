#pragma once
// Contract: the linear brightness of one pixel of an 8-bit sRGB-ish RGBA8 readback, for tests that compare
// regions of rendered PNG-like frames: the sum of the three channels decoded with gamma 2.2 (not a
// photometric luminance; equal weights, so ratios of sums compare like with like).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hp::test {
inline double rgbaLinearSum(const std::vector<std::uint8_t>& rgba, std::size_t px) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += std::pow(rgba[px * 4 + c] / 255.0, 2.2);
  return sum;
}
}  // namespace hp::test
