// HairMaterial::validate() and the colour <-> absorption conversion (see material_color.h).
#include "engine/core/shading/material.h"

#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/error.h"
#include "engine/core/shading/material_color.h"

namespace hp {
namespace {
bool isAngle(const std::string& field) { return field == "alphaR" || field == "betaR" || field == "wc" || field == "betaN" ||
                                                 field == "tiltVariation"; }

[[noreturn]] void fail(const std::string& field, double value, const char* rule) {
  std::ostringstream os;
  os << "HairMaterial." << field << " = " << value;
  if (isAngle(field)) os << " rad (" << value * 180.0 / 3.14159265358979323846 << " deg)";
  os << " is invalid: " << rule;
  throw Error(os.str());
}

void requireFinite(const std::string& field, double value) {
  if (!std::isfinite(value)) fail(field, value, "must be finite");
}

void requireRange(const std::string& field, double value, double lo, bool loOpen, double hi,
                  const char* rule) {
  requireFinite(field, value);
  bool lowOk = loOpen ? value > lo : value >= lo;
  if (!lowOk || value > hi) fail(field, value, rule);
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;
}  // namespace

void HairMaterial::validate() const {
  requireRange("eta", eta, 1.0, true, 3.0, "must be in (1, 3]");
  for (int c = 0; c < 3; ++c) {
    std::string field = std::string("absorption[") + "rgb"[c] + "]";
    requireRange(field, absorption[c], 0.0, false, 1e6, "must be in [0, 1e6] (per unit radius)");
  }
  requireRange("alphaR", alphaR, -30 * kDeg, false, 30 * kDeg, "|alphaR| must be <= 30 deg");
  requireRange("betaR", betaR, 0.0, true, 45 * kDeg, "must be in (0, 45] deg");
  requireRange("kG", kG, 0.0, false, 1e6, "must be in [0, 1e6]");
  requireRange("wc", wc, 0.0, true, 90 * kDeg, "must be in (0, 90] deg");
  requireRange("dEta", dEta, 0.0, true, 10.0, "must be in (0, 10]");
  requireRange("dhM", dhM, 0.0, true, 1.0, "must be in (0, 1]");
  requireRange("betaN", betaN, 2 * kDeg, false, 45 * kDeg, "must be in [2, 45] deg");
  requireRange("tiltVariation", tiltVariation, 0.0, false, 10 * kDeg, "must be in [0, 10] deg");
  // 0 or at least 0.01: a smaller variation reaches the shader as a float denormal, which a device may flush to 0
  // and then read the M texture's 7 layers as one.
  if (roughnessVariation != 0.0)
    requireRange("roughnessVariation", roughnessVariation, 0.01, false, 0.25, "must be 0 or in [0.01, 0.25]");
}

glm::dvec3 absorptionFromColor(glm::dvec3 rgb) {
  glm::dvec3 sigma;
  for (int c = 0; c < 3; ++c) {
    double v = rgb[c];
    if (!std::isfinite(v) || v <= 0.0 || v > 1.0) {
      std::ostringstream os;
      os << "color[" << "rgb"[c] << "] = " << v << " is invalid: must be in (0, 1]";
      throw Error(os.str());
    }
    sigma[c] = -std::log(v) / 2.0;
  }
  return sigma;
}

glm::dvec3 colorFromAbsorption(glm::dvec3 sigmaA) { return glm::exp(-2.0 * sigmaA); }
}  // namespace hp
