#include "engine/core/hair/sim_params.h"

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "shaders/shared/hair_grid.h"

namespace hp {
namespace {
std::string show(double v) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "Inf" : "-Inf";
  std::string s = std::to_string(v);
  return s;
}

void check(bool ok, const char* field, const std::string& rule, double value) {
  if (!ok) throw Error(std::string("simulation parameter ") + field + " " + rule + ", got " + show(value));
}

void checkRange(double v, double lo, double hi, const char* field) {
  check(std::isfinite(v) && v >= lo && v <= hi, field,
        "must be in [" + show(lo) + ", " + show(hi) + "]", v);
}

void checkVector(const glm::dvec3& v, const char* field) {
  for (int i = 0; i < 3; ++i)
    check(std::isfinite(v[i]), field, "must be finite (component " + std::to_string(i) + ")", v[i]);
}
}  // namespace

void SimulationParams::validate() const {
  check(std::isfinite(dt) && dt > 0.0 && dt <= 1.0, "dt", "must be in (0, 1] seconds", dt);
  check(substeps >= 1 && substeps <= 64, "substeps", "must be in [1, 64]", substeps);
  check(iterations >= 1 && iterations <= 1000, "iterations", "must be in [1, 1000]", iterations);
  checkVector(gravity, "gravity");
  checkRange(damping, 0.0, 1.0, "damping");
  check(std::isfinite(pearlRadius) && pearlRadius >= 0.0, "pearlRadius", "must be >= 0", pearlRadius);
  checkRange(stiffness, 0.0, 1.0, "stiffness");
  checkRange(stiffnessFalloff, 0.0, 1.0, "stiffnessFalloff");
  checkRange(localStiffness, 0.0, 0.9, "localStiffness");
  check(std::isfinite(maxSpeed) && maxSpeed > 0.0, "maxSpeed", "must be > 0", maxSpeed);
  checkRange(volume, 0.0, 10.0, "volume");
  checkRange(volumeTarget, 0.01, 100.0, "volumeTarget");
  checkRange(friction, 0.0, 1.0, "friction");
  check(gridResolution >= gpu::GRID_MIN_RESOLUTION && gridResolution <= gpu::GRID_MAX_RESOLUTION, "gridResolution",
        "must be in [" + std::to_string(gpu::GRID_MIN_RESOLUTION) + ", " + std::to_string(gpu::GRID_MAX_RESOLUTION) + "]",
        gridResolution);
  checkVector(windDirection, "windDirection");
  check(std::isfinite(windStrength) && windStrength >= 0.0, "windStrength", "must be >= 0", windStrength);
  if (windStrength > 0.0)
    check(glm::length(windDirection) > 0.0, "windDirection", "must be non-zero when windStrength > 0",
          glm::length(windDirection));
  checkRange(windGust, 0.0, 1.0, "windGust");
  check(std::isfinite(windGustFrequency) && windGustFrequency >= 0.0, "windGustFrequency", "must be >= 0",
        windGustFrequency);
}
}  // namespace hp
