#pragma once
// Contract: a number as hairpipe's error messages show it: a whole number exactly (a count or index read
// from a file: 300000000), anything else with at most 6 significant digits and no trailing zeros (printf's
// %g: 0.95, 1e-05, 1.5e+20), NaN and Inf spelled out. std::to_string prints every double with six decimals
// (100000.000000, 0.000010), which reads as a precision the bound does not have.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace hp {
inline std::string numberText(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  if (std::abs(v) < 9e15 && v == std::floor(v)) return std::to_string(std::int64_t(v));
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}
}  // namespace hp
