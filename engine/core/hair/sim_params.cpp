#include "engine/core/hair/sim_params.h"

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "shaders/shared/hair_grid.h"

namespace hp {
namespace {
void check(bool ok, const char* field, const std::string& rule, double value) {
  if (!ok) throw Error(std::string("simulation parameter ") + field + " " + rule + ", got " + numberText(value));
}

void checkRange(double v, double lo, double hi, const char* field) {
  check(std::isfinite(v) && v >= lo && v <= hi, field,
        "must be in [" + numberText(lo) + ", " + numberText(hi) + "]", v);
}

void checkVector(const glm::dvec3& v, const char* field) {
  for (int i = 0; i < 3; ++i)
    check(std::isfinite(v[i]), field, "must be finite (component " + std::to_string(i) + ")", v[i]);
}

// Accelerations, lengths and rates past these take the particles past single precision in a few steps (every
// particle NaN, the run otherwise "successful"); each is generous in any unit a scene uses (metres to mm).
constexpr double kMaxAcceleration = 1.0e5;  // scene units / s^2: 10,000 g in metres
constexpr double kMaxPearlRadius = 1.0e3;   // scene units
constexpr double kMaxSpeed = 1.0e6;         // scene units / s
constexpr double kMaxGustFrequency = 1.0e3; // Hz
}  // namespace

void SimulationParams::validate() const {
  check(std::isfinite(dt) && dt > 0.0 && dt <= 1.0, "dt", "must be in (0, 1] seconds", dt);
  check(substeps >= 1 && substeps <= 64, "substeps", "must be in [1, 64]", substeps);
  check(iterations >= 1 && iterations <= 1000, "iterations", "must be in [1, 1000]", iterations);
  checkVector(gravity, "gravity");
  check(glm::length(gravity) <= kMaxAcceleration, "gravity", "must be at most " + numberText(kMaxAcceleration) + " long",
        glm::length(gravity));
  checkRange(damping, 0.0, 1.0, "damping");
  checkRange(pearlRadius, 0.0, kMaxPearlRadius, "pearlRadius");
  checkRange(stiffness, 0.0, 1.0, "stiffness");
  checkRange(stiffnessFalloff, 0.0, 1.0, "stiffnessFalloff");
  checkRange(localStiffness, 0.0, 0.9, "localStiffness");
  check(std::isfinite(maxSpeed) && maxSpeed > 0.0 && maxSpeed <= kMaxSpeed, "maxSpeed",
        "must be in (0, " + numberText(kMaxSpeed) + "]", maxSpeed);
  checkRange(volume, 0.0, 10.0, "volume");
  checkRange(volumeTarget, 0.01, 100.0, "volumeTarget");
  checkRange(friction, 0.0, 1.0, "friction");
  check(gridResolution >= gpu::GRID_MIN_RESOLUTION && gridResolution <= gpu::GRID_MAX_RESOLUTION, "gridResolution",
        "must be in [" + std::to_string(gpu::GRID_MIN_RESOLUTION) + ", " + std::to_string(gpu::GRID_MAX_RESOLUTION) + "]",
        gridResolution);
  checkVector(windDirection, "windDirection");
  checkRange(windStrength, 0.0, kMaxAcceleration, "windStrength");
  if (windStrength > 0.0)
    check(glm::length(windDirection) > 0.0, "windDirection", "must be non-zero when windStrength > 0",
          glm::length(windDirection));
  checkRange(windGust, 0.0, 1.0, "windGust");
  checkRange(windGustFrequency, 0.0, kMaxGustFrequency, "windGustFrequency");
}
}  // namespace hp
