#pragma once
// Contract: RGBA8 readbacks compared in tests: the linear brightness of one pixel (the sum of the three
// channels decoded with gamma 2.2: not a photometric luminance; equal weights, so ratios of sums compare like
// with like), how many pixels of two images of one size are apart by more than some levels in a channel, and
// the largest difference of a channel.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hp::test {
inline double rgbaLinearSum(const std::vector<std::uint8_t>& rgba, std::size_t px) {
  double sum = 0.0;
  for (int c = 0; c < 3; ++c) sum += std::pow(rgba[px * 4 + c] / 255.0, 2.2);
  return sum;
}

// Pixels whose RGBA channels differ by more than `levels` in any channel (0: any difference at all).
inline std::size_t pixelsApart(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int levels) {
  std::size_t n = 0;
  for (std::size_t px = 0; px < a.size() / 4; ++px)
    for (int c = 0; c < 4; ++c)
      if (std::abs(int(a[px * 4 + c]) - int(b[px * 4 + c])) > levels) {
        ++n;
        break;
      }
  return n;
}

inline int largestDifference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  int largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(int(a[i]) - int(b[i])));
  return largest;
}
}  // namespace hp::test
