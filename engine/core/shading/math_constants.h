#pragma once
// Constants the shading code's files share (one definition, so a unity build sees no duplicates).
#include <numbers>

namespace hp::shading {
inline constexpr double kPi = std::numbers::pi;
}  // namespace hp::shading
