#include "compute/raster/list_sizing.h"

#include <algorithm>

namespace hp::compute {

std::uint32_t ListSizing::next(std::uint64_t need, std::uint32_t capacity) {
  if (need * 4 > std::uint64_t(capacity) * 3) {
    quietFrames_ = 0;
    quietPeak_ = 0;
    return capacity < max_ ? std::uint32_t(std::min<std::uint64_t>(need * 2, max_)) : 0;
  }
  if (shrinkFrames_ == 0 || need * 4 >= capacity || capacity <= floor_) {
    quietFrames_ = 0;
    quietPeak_ = 0;
    return 0;
  }
  quietPeak_ = std::max(quietPeak_, need);
  if (++quietFrames_ < shrinkFrames_) return 0;
  const std::uint64_t smaller = std::max<std::uint64_t>(quietPeak_ * 2, floor_);
  quietFrames_ = 0;
  quietPeak_ = 0;
  return smaller < capacity ? std::uint32_t(smaller) : 0;
}

}  // namespace hp::compute
