#include "engine/core/shading/multiple_scattering.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/shading/furnace.h"
#include "engine/core/shading/math_constants.h"
#include "engine/core/shading/physical_terms.h"

namespace hp {
namespace {
constexpr int kPanels = 16;
using Lobes = std::array<glm::dvec3, 3>;

// Mean and variance of theta_i + theta_r after one scattering event into one half of the azimuths: the
// lobes' shifts and variances mixed by the energy each lobe sends there (per RGB).
struct EventSpread {
  glm::dvec3 mean{0.0}, variance{0.0};
};
EventSpread eventSpread(const Lobes& energy, const HairMaterial& m) {
  glm::dvec3 total(0.0), first(0.0), second(0.0);
  for (int p = 0; p < 3; ++p) {
    const double s = shading::physicalShift(p, m), v = shading::physicalVariance(p, m);
    total += energy[p];
    first += energy[p] * s;
    second += energy[p] * (v + s * s);
  }
  const glm::dvec3 safe = glm::max(total, glm::dvec3(1e-300));
  return {first / safe, second / safe - (first / safe) * (first / safe)};
}

// a_f, a_b, A_b and its lobe's shift and width, from the lobes' energies into the far and near halves.
void addAlbedosAndBackScattering(MultipleScatteringTables& t, const Lobes& fwd, const Lobes& back,
                                 const HairMaterial& m) {
  // Each albedo is at most 1; the quadrature of a lobe narrower than its panels can overshoot.
  const glm::dvec3 af = glm::clamp(fwd[0] + fwd[1] + fwd[2], 0.0, 1.0);
  const glm::dvec3 ab = glm::clamp(back[0] + back[1] + back[2], 0.0, 1.0);
  const glm::dvec3 q = glm::min(af * af, glm::dvec3(0.999));  // a_f^2 < 1: some light is absorbed or lost
  const glm::dvec3 A = glm::min(ab * q / (1.0 - q) + ab * ab * ab * q / ((1.0 - q) * (1.0 - q) * (1.0 - q)),
                                glm::dvec3(1.0));
  const EventSpread f = eventSpread(fwd, m), b = eventSpread(back, m);
  const glm::dvec3 pairs = 1.0 / (1.0 - q), pairsVariance = q / ((1.0 - q) * (1.0 - q));
  const glm::dvec3 mean = b.mean + 2.0 * pairs * f.mean;
  const glm::dvec3 variance = b.variance + 2.0 * pairs * f.variance + 4.0 * f.mean * f.mean * pairsVariance;
  const double weight = std::max(A.r + A.g + A.b, 1e-300);
  const double shift = glm::dot(A, mean) / weight;
  const double width = std::sqrt(std::max(glm::dot(A, variance) / weight, 1e-8));
  t.forwardAlbedo.push_back(af);
  t.backAlbedo.push_back(ab);
  t.backScatter.push_back(A);
  t.backShift.push_back(shift);
  t.backWidth.push_back(width);
}
}  // namespace

MultipleScatteringTables multipleScatteringTables(const HairMaterial& m, int entries) {
  if (entries < 2 || entries > 1024) throw Error("multiple scattering tables: entries must be in [2, 1024]");
  m.validate();
  MultipleScatteringTables t;
  for (int k = 0; k < entries; ++k) {
    const double s = std::clamp(-1.0 + 2.0 * k / (entries - 1), -kEdgeSine, kEdgeSine);
    const Lobes fwd = physicalLobeFurnaceOver(s, m, 0.5 * shading::kPi, shading::kPi, kPanels);
    const Lobes back = physicalLobeFurnaceOver(s, m, 0.0, 0.5 * shading::kPi, kPanels);
    addAlbedosAndBackScattering(t, fwd, back, m);
    const auto energy = shading::physicalLobeEnergy(s, m);  // int N_p d phi over the whole circle
    t.meanR.push_back(energy[0].x / (2.0 * shading::kPi));
    t.meanTT.push_back(energy[1] / (2.0 * shading::kPi));
    t.meanTRT.push_back((energy[2] + energy[3]) / (2.0 * shading::kPi));
  }
  return t;
}

glm::dvec2 backLobeAt(const MultipleScatteringTables& t, double sinTheta) {
  const int n = int(t.backShift.size());
  if (n < 2) throw Error("backLobeAt: the tables need at least 2 entries");
  const double x = std::clamp(0.5 * sinTheta + 0.5, 0.0, 1.0) * (n - 1);
  const int i = std::min(int(x), n - 2);
  const double f = x - i;
  return {(1.0 - f) * t.backShift[i] + f * t.backShift[i + 1], (1.0 - f) * t.backWidth[i] + f * t.backWidth[i + 1]};
}

glm::dvec3 meanForwardAlbedo(const MultipleScatteringTables& t) {
  // The entries are even in sin theta, where cos^2 theta d theta = cos theta d(sin theta): trapezoids.
  const int n = int(t.forwardAlbedo.size());
  glm::dvec3 sum(0.0);
  double weights = 0.0;
  for (int i = 0; i < n; ++i) {
    const double s = std::clamp(-1.0 + 2.0 * i / (n - 1), -kEdgeSine, kEdgeSine);
    const double w = std::sqrt(1.0 - s * s) * (i == 0 || i == n - 1 ? 0.5 : 1.0);
    sum += w * t.forwardAlbedo[i];
    weights += w;
  }
  return sum / weights;
}

glm::dvec3 skyVisibility(const MultipleScatteringTables& t) {
  const glm::dvec3 k = glm::clamp(1.0 - meanForwardAlbedo(t), 1e-9, 1.0);
  return 0.5 * (1.0 - k * glm::log(1.0 + 1.0 / k));
}
}  // namespace hp
