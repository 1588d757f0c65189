#include "engine/shading/multiple_scattering.h"

#include <algorithm>

#include "engine/error.h"
#include "engine/shading/furnace.h"
#include "engine/shading/math_constants.h"
#include "engine/shading/physical_terms.h"

namespace hp {
namespace {
constexpr int kPanels = 16;
}  // namespace

MultipleScatteringTables multipleScatteringTables(const HairMaterial& m, int entries) {
  if (entries < 2 || entries > 1024) throw Error("multiple scattering tables: entries must be in [2, 1024]");
  m.validate();
  MultipleScatteringTables t;
  for (int k = 0; k < entries; ++k) {
    const double s = std::clamp(-1.0 + 2.0 * k / (entries - 1), -kEdgeSine, kEdgeSine);
    t.forwardAlbedo.push_back(physicalFurnaceOver(s, m, 0.5 * shading::kPi, shading::kPi, kPanels));
    const auto energy = shading::physicalLobeEnergy(s, m);  // int N_p d phi over the whole circle
    t.meanR.push_back(energy[0].x / (2.0 * shading::kPi));
    t.meanTT.push_back(energy[1] / (2.0 * shading::kPi));
    t.meanTRT.push_back((energy[2] + energy[3]) / (2.0 * shading::kPi));
  }
  return t;
}
}  // namespace hp
