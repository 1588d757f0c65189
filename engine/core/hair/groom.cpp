#include "engine/core/hair/groom.h"

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/number_text.h"

namespace hp {
namespace {
void checkRange(const char* field, float value, float lo, float hi) {
  if (!(value >= lo && value <= hi))
    throw Error(std::string("GroomSettings.") + field + " must be in [" + numberText(lo) + ", " + numberText(hi) +
                "], got " + numberText(value));
}
}  // namespace

void GroomSettings::validate() const {
  if (clumpsPerTriangle > 64)
    throw Error("GroomSettings.clumpsPerTriangle must be in [0, 64], got " + std::to_string(clumpsPerTriangle));
  checkRange("clumpStrength", clumpStrength, 0.0f, 1.0f);
  checkRange("clumpShape", clumpShape, 0.1f, 10.0f);
  checkRange("curlRadius", curlRadius, 0.0f, 1.0f);
  checkRange("curlTurns", curlTurns, 0.0f, 10000.0f);
  checkRange("curlVariation", curlVariation, 0.0f, 1.0f);
  checkRange("frizzAmplitude", frizzAmplitude, 0.0f, 1.0f);
  if (!(frizzFrequency > 0.0f && frizzFrequency <= 10000.0f))
    throw Error("GroomSettings.frizzFrequency must be in (0, 10000], got " + numberText(frizzFrequency));
  checkRange("frizzHairline", frizzHairline, 0.0f, 100.0f);
  if (!(frizzHairlineWidth > 0.0f && frizzHairlineWidth <= 10.0f))
    throw Error("GroomSettings.frizzHairlineWidth must be in (0, 10], got " + numberText(frizzHairlineWidth));
}

gpu::GroomParams groomParams(const GroomSettings& g) {
  gpu::GroomParams p{};
  p.clump = glm::vec4(float(g.clumpsPerTriangle), g.clumpStrength, g.clumpShape, 0.0f);
  p.curl = glm::vec4(g.curlRadius, g.curlTurns, g.curlVariation, 0.0f);
  p.frizz = glm::vec4(g.frizzAmplitude, g.frizzFrequency, g.frizzHairline, g.frizzHairlineWidth);
  return p;
}
}  // namespace hp
