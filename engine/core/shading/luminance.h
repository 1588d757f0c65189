#pragma once
// Contract: the luminance of linear RGB with Rec. 709 primaries (the weights of the sRGB display path), the
// one definition the environment's split, the reference's environment sampling and the image comparisons use.
#include <glm/glm.hpp>

namespace hp {
inline double luminanceOf(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }
}  // namespace hp
