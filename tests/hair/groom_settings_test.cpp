// GroomSettings: every field refused outside its range by name (NaN included); the default adds nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "engine/core/error.h"
#include "engine/core/hair/groom.h"

using hp::GroomSettings;

TEST(GroomSettings, RefusesEachFieldOutsideItsRangeByName) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::pair<const char*, std::function<void(GroomSettings&)>> cases[] = {
      {"clumpsPerTriangle", [](GroomSettings& g) { g.clumpsPerTriangle = 65; }},
      {"clumpStrength", [&](GroomSettings& g) { g.clumpStrength = nan; }},
      {"clumpStrength", [](GroomSettings& g) { g.clumpStrength = 1.5f; }},
      {"clumpShape", [](GroomSettings& g) { g.clumpShape = 0.0f; }},
      {"curlRadius", [](GroomSettings& g) { g.curlRadius = -0.001f; }},
      {"curlTurns", [&](GroomSettings& g) { g.curlTurns = std::numeric_limits<float>::infinity(); }},
      {"curlVariation", [](GroomSettings& g) { g.curlVariation = 2.0f; }},
      {"frizzAmplitude", [&](GroomSettings& g) { g.frizzAmplitude = nan; }},
      {"frizzFrequency", [](GroomSettings& g) { g.frizzFrequency = 0.0f; }},
      {"frizzHairline", [](GroomSettings& g) { g.frizzHairline = -1.0f; }},
      {"frizzHairline", [&](GroomSettings& g) { g.frizzHairline = nan; }},
      {"frizzHairlineWidth", [](GroomSettings& g) { g.frizzHairlineWidth = 0.0f; }},
  };
  for (const auto& [field, spoil] : cases) {
    GroomSettings g;
    spoil(g);
    try {
      g.validate();
      ADD_FAILURE() << field << " was accepted";
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("GroomSettings.") + field), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(GroomSettings{}.validate());
  EXPECT_FALSE(GroomSettings{}.any());
}
