#include "engine/hair/segment_profile.h"

#include <cmath>
#include <string>

#include "engine/error.h"

namespace hp {
std::vector<float> geometricSegmentLengths(float total, float ratio, std::uint32_t segments) {
  if (segments == 0) throw Error("segment profile: need at least one segment");
  if (!std::isfinite(total) || total <= 0.0f)
    throw Error("segment profile: total length must be positive, got " + std::to_string(total));
  if (!std::isfinite(ratio) || ratio < 1.0f || ratio > 4.0f)
    throw Error("segment profile: segment ratio must be in [1, 4], got " + std::to_string(ratio));
  // Geometric series in double so the lengths sum to total to float precision.
  double sum = 0.0, w = 1.0;
  for (std::uint32_t k = 0; k < segments; ++k, w *= ratio) sum += w;
  std::vector<float> out(segments);
  w = 1.0;
  for (std::uint32_t k = 0; k < segments; ++k, w *= ratio) out[k] = static_cast<float>(total * w / sum);
  return out;
}

std::vector<float> geometricArcPositions(float total, float ratio, std::uint32_t segments) {
  std::vector<float> lengths = geometricSegmentLengths(total, ratio, segments);
  std::vector<float> out(segments + 1, 0.0f);
  double s = 0.0;
  for (std::uint32_t k = 0; k < segments; ++k) out[k + 1] = static_cast<float>(s += lengths[k]);
  out[segments] = total;  // exact tip
  return out;
}
}  // namespace hp
