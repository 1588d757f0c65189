#pragma once
// Contract: the growing tile lists' size policy (RasterSettings::growLists), pure arithmetic so tests drive it
// frame by frame. Fed each frame's need (the most list entries a view of that frame asked for, listNeed) and
// the newest lists' capacity, it answers the capacity of new lists, or 0 to keep them:
// - grow: a need over 3/4 of the capacity asks for twice the need (at most `max`);
// - shrink: `shrinkFrames` frames in a row that each need under 1/4 of the capacity ask for twice the most
//   they needed (at least `floor`), so a close-up's lists do not stay reserved for the rest of a session and
//   the new size sits between the two thresholds (no grow and shrink back and forth). 0: never shrink.
#include <cstdint>

namespace hp::compute {

class ListSizing {
 public:
  ListSizing(std::uint32_t floor, std::uint32_t max, std::uint32_t shrinkFrames)
      : floor_(floor), max_(max), shrinkFrames_(shrinkFrames) {}
  // One frame's need against the lists' capacity: the capacity to make, or 0 to keep the lists.
  std::uint32_t next(std::uint64_t need, std::uint32_t capacity);

 private:
  std::uint32_t floor_, max_, shrinkFrames_;
  std::uint32_t quietFrames_ = 0;  // frames in a row that needed under a quarter of the capacity
  std::uint64_t quietPeak_ = 0;    // the most any of them needed
};

}  // namespace hp::compute
