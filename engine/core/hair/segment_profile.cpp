#include "engine/core/hair/segment_profile.h"

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/number_text.h"

namespace hp {
std::vector<float> geometricSegmentLengths(float total, float ratio, std::uint32_t segments) {
  if (segments == 0) throw Error("segment profile: need at least one segment");
  if (!std::isfinite(total) || total <= 0.0f)
    throw Error("segment profile: total length must be positive, got " + numberText(total));
  if (!std::isfinite(ratio) || ratio < 1.0f || ratio > 4.0f)
    throw Error("segment profile: segment ratio must be in [1, 4], got " + numberText(ratio));
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
float polylineLength(std::span<const glm::vec3> points) {
  double s = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) s += glm::length(points[i] - points[i - 1]);
  return static_cast<float>(s);
}

void resamplePolyline(std::span<const glm::vec3> points, std::uint32_t particles, float ratio,
                      std::span<glm::vec3> out) {
  if (points.size() < 2 || particles < 2 || out.size() != particles)
    throw Error("resample: need >= 2 input points and an output of >= 2 particles");
  float total = polylineLength(points);
  if (!(total > 0.0f)) {
    for (auto& p : out) p = points.front();
    return;
  }
  std::vector<float> targets = geometricArcPositions(total, ratio, particles - 1);
  // Walk the input once: targets increase, so the segment cursor only moves forward.
  std::size_t seg = 0;
  double segStart = 0.0;
  double segLen = glm::length(points[1] - points[0]);
  for (std::uint32_t k = 0; k < particles; ++k) {
    while (seg + 2 < points.size() && segStart + segLen < targets[k]) {
      segStart += segLen;
      ++seg;
      segLen = glm::length(points[seg + 1] - points[seg]);
    }
    double t = segLen > 0.0 ? (targets[k] - segStart) / segLen : 0.0;
    out[k] = glm::mix(points[seg], points[seg + 1], static_cast<float>(glm::clamp(t, 0.0, 1.0)));
  }
  out.front() = points.front();
  out.back() = points.back();
}
}  // namespace hp
