#include "samples/cli/material_options.h"

#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/shading/material_color.h"

namespace hp::cli {
namespace {
// Applies `set` to a copy, validates it, and only then commits: errors name the option.
void applyChecked(HairMaterial& material, const std::string& option, const std::string& text,
                  const std::function<void(HairMaterial&)>& set) {
  HairMaterial next = material;
  try {
    set(next);
    next.validate();
  } catch (const Error& e) {
    throw Error(option + " " + text + ": " + e.what());
  }
  material = next;
}

std::string joined(const std::vector<double>& v) {
  std::ostringstream os;
  for (std::size_t i = 0; i < v.size(); ++i) os << (i ? "," : "") << v[i];
  return os.str();
}

constexpr const char* kGroup = "Hair material";

void addScalar(CLI::App& app, HairMaterial& m, const std::string& name, const std::string& help,
               std::function<void(HairMaterial&, double)> set) {
  app.add_option_function<double>(
         name,
         [&m, name, set](double v) {
           std::ostringstream text;
           text << v;
           applyChecked(m, name, text.str(), [&](HairMaterial& x) { set(x, v); });
         },
         help)
      ->group(kGroup);
}
}  // namespace

void addMaterialOptions(CLI::App& app, HairMaterial& m) {
  addScalar(app, m, "--eta", "index of refraction, (1, 3] (default 1.55)", [](HairMaterial& x, double v) { x.eta = v; });
  addScalar(app, m, "--alpha-r", "R lobe shift in degrees, |.| <= 30 (default -7.5)",
            [](HairMaterial& x, double v) { x.alphaR = glm::radians(v); });
  addScalar(app, m, "--beta-r", "R lobe width in degrees, (0, 45] (default 7.5)",
            [](HairMaterial& x, double v) { x.betaR = glm::radians(v); });
  addScalar(app, m, "--kg", "caustic glint scale, >= 0 (default 0.5)", [](HairMaterial& x, double v) { x.kG = v; });
  addScalar(app, m, "--wc", "caustic azimuthal width in degrees, (0, 90] (default 15)",
            [](HairMaterial& x, double v) { x.wc = glm::radians(v); });
  addScalar(app, m, "--deta", "caustic fade range of eta', > 0 (default 0.3)", [](HairMaterial& x, double v) { x.dEta = v; });
  addScalar(app, m, "--dhm", "caustic maximum h range, (0, 1] (default 0.5)", [](HairMaterial& x, double v) { x.dhM = v; });
  addScalar(app, m, "--beta-n", "physical model: azimuthal lobe width in degrees, [2, 45] (default 10)",
            [](HairMaterial& x, double v) { x.betaN = glm::radians(v); });
  addScalar(app, m, "--tilt-variation",
            "per-strand cuticle tilt variation in degrees: each strand's alpha R is offset by up to this much, [0, 10] "
            "(default 2; physical and direct lookup modes)",
            [](HairMaterial& x, double v) { x.tiltVariation = glm::radians(v); });
  addScalar(app, m, "--roughness-variation",
            "per-strand roughness variation: each strand's beta R is scaled by one of 7 levels over 1 +- this, 0 or [0.01, 0.25] "
            "(default 0.15; physical and direct lookup modes)",
            [](HairMaterial& x, double v) { x.roughnessVariation = v; });
  auto* absorption = app.add_option_function<std::vector<double>>(
      "--absorption",
      [&m](const std::vector<double>& v) {
        applyChecked(m, "--absorption", joined(v), [&](HairMaterial& x) { x.absorption = {v[0], v[1], v[2]}; });
      },
      "sigma_a per unit fibre radius R,G,B (default 0.55,0.91,1.78)");
  auto* color = app.add_option_function<std::vector<double>>(
      "--color",
      [&m](const std::vector<double>& v) {
        applyChecked(m, "--color", joined(v),
                     [&](HairMaterial& x) { x.absorption = absorptionFromColor({v[0], v[1], v[2]}); });
      },
      "hair colour R,G,B in (0, 1]: transmittance of one pass through the fibre centre; sets "
      "sigma_a = -ln(c)/2");
  for (CLI::Option* o : {absorption, color}) o->delimiter(',')->expected(3)->group(kGroup);
  absorption->excludes(color);
}
// Every option of the group, so that none added later is forgotten here.
bool materialGiven(const CLI::App& app) {
  for (const CLI::Option* o : app.get_options([](const CLI::Option* o) { return o->get_group() == kGroup; }))
    if (o->count() > 0) return true;
  return false;
}
}  // namespace hp::cli
