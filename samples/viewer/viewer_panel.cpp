#include "samples/viewer/viewer_panel.h"

#include <imgui.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <string>

namespace hp::viewer {
namespace {
// ImGui edits floats; the parameters are doubles (and radians where the UI shows degrees).
bool editDouble(const char* label, double& value, float lo, float hi, const char* format = "%.3f") {
  float v = float(value);
  if (!ImGui::SliderFloat(label, &v, lo, hi, format)) return false;
  value = v;
  return true;
}

bool editDegrees(const char* label, double& radians, float lo, float hi) {
  float deg = float(radians * 180.0 / std::numbers::pi);
  if (!ImGui::SliderFloat(label, &deg, lo, hi, "%.1f deg")) return false;
  radians = deg * std::numbers::pi / 180.0;
  return true;
}

bool editCount(const char* label, std::uint32_t& value, int lo, int hi) {
  int v = int(value);
  if (!ImGui::SliderInt(label, &v, lo, hi)) return false;
  value = std::uint32_t(v);
  return true;
}

void simulationSection(Tunables& t, ViewState& view, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const char* animations[] = {"none", "nod", "turn", "shake"};
  int a = int(view.animation);
  if (a > 3) a = 0;
  if (ImGui::Combo("animation (N/T/S)", &a, animations, 4)) {
    view.animation = HeadAnimation(a);
    view.animationChanged = true;
  }
  ImGui::Checkbox("paused (Space)", &view.paused);
  c.simulation |= ImGui::Checkbox("wind (W)", &view.wind);
  c.simulation |= editDouble("wind strength", t.windStrength, 0.0f, 30.0f);
  c.simulation |= editDouble("wind gust", t.simulation.windGust, 0.0f, 1.0f);
  c.simulation |= editCount("substeps", t.simulation.substeps, 1, 8);
  c.simulation |= editCount("iterations", t.simulation.iterations, 1, 32);
  c.simulation |= editDouble("damping", t.simulation.damping, 0.0f, 0.5f);
  c.simulation |= editDouble("stiffness", t.simulation.stiffness, 0.0f, 1.0f);
  c.simulation |= editDouble("local shape", t.simulation.localStiffness, 0.0f, 0.9f);
  c.simulation |= editDouble("volume", t.simulation.volume, 0.0f, 3.0f);
  c.simulation |= editDouble("volume target", t.simulation.volumeTarget, 0.1f, 10.0f);
  c.simulation |= editDouble("friction", t.simulation.friction, 0.0f, 1.0f);
}

void densitySection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Density")) return;
  int d = int(t.density);
  ImGui::SliderInt("render strands", &d, 1000, 200000, "%d", ImGuiSliderFlags_Logarithmic);
  t.density = std::uint32_t(d);
  c.density = ImGui::Button("apply density");
}

void materialSection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Material and scattering")) return;
  float sigma[3] = {float(t.material.absorption.x), float(t.material.absorption.y), float(t.material.absorption.z)};
  if (ImGui::SliderFloat3("absorption", sigma, 0.0f, 8.0f)) t.material.absorption = {sigma[0], sigma[1], sigma[2]};
  editDouble("eta", t.material.eta, 1.2f, 2.0f);
  editDegrees("alpha R (shift)", t.material.alphaR, -12.0f, 0.0f);
  editDegrees("beta R (width)", t.material.betaR, 2.0f, 20.0f);
  editDegrees("tilt variation", t.material.tiltVariation, 0.0f, 10.0f);
  editDouble("roughness variation", t.material.roughnessVariation, 0.0f, 0.25f);
  editDouble("glint kG", t.material.kG, 0.0f, 2.0f);
  editDegrees("glint width wc", t.material.wc, 5.0f, 30.0f);
  const char* modes[] = {lutModeName(LutMode::Direct), lutModeName(LutMode::Paper), lutModeName(LutMode::Float),
                         lutModeName(LutMode::Physical)};  // LutMode's order: the combo's index is the mode
  int m = int(t.lutMode);
  ImGui::Combo("lookup", &m, modes, 4);
  t.lutMode = LutMode(m);
  c.material = ImGui::Button("apply material");
}

constexpr const char* kLightTypes[] = {"directional", "spot", "point"};  // LightSpec::Type's order

// A spot aims from its position at its target; a degenerate pair keeps the last direction.
void aimSpot(EditedLight& e) {
  const glm::vec3 d = e.light.position - e.target;
  if (glm::length(d) > 1e-6f) e.light.direction = glm::normalize(d);
}

// Another type keeps where the light comes from: a directional light's direction becomes a position at a
// head-sized distance from the aim centre, and a position becomes the direction from it.
void changeType(EditedLight& e, LightSpec::Type type, const ViewState& view) {
  const glm::vec3 toward = view.towardLightOf(e);
  if (e.light.type == LightSpec::Type::Directional)
    e.light.position = view.camera.target + toward * (0.7f * view.baseDistance);
  if (type == LightSpec::Type::Spot && e.light.type != LightSpec::Type::Spot) e.target = view.camera.target;
  e.light.type = type;
  e.light.direction = toward;
  if (type == LightSpec::Type::Spot) aimSpot(e);
}

bool editVec3(const char* label, glm::vec3& v, float speed) { return ImGui::DragFloat3(label, &v.x, speed); }

// Where the light shines from: a direction, or a position (and a spot's target, cone); the falloff range.
bool editPlacement(EditedLight& e) {
  LightSpec& l = e.light;
  if (l.type == LightSpec::Type::Directional) {
    glm::vec3 d = l.direction;
    if (!ImGui::SliderFloat3("direction", &d.x, -1.0f, 1.0f) || !(glm::length(d) > 1e-3f)) return false;
    l.direction = glm::normalize(d);
    return true;
  }
  bool changed = editVec3("position", l.position, 0.005f);
  if (l.type == LightSpec::Type::Spot) {
    changed |= editVec3("target", e.target, 0.005f);
    changed |= ImGui::SliderFloat("cone (deg)", &l.coneDeg, 1.0f, 80.0f, "%.1f");
    aimSpot(e);
  }
  changed |= ImGui::SliderFloat("range (0: none)", &l.range, 0.0f, 4.0f, "%.2f");
  return changed;
}

// One light's controls; true when it changed.
bool editLight(EditedLight& e, const ViewState& view) {
  bool changed = false;
  int type = int(e.light.type);
  if (ImGui::Combo("type", &type, kLightTypes, 3)) {
    changeType(e, LightSpec::Type(type), view);
    changed = true;
  }
  changed |= editPlacement(e);
  changed |= ImGui::ColorEdit3("color", &e.light.color.x);
  changed |= ImGui::SliderFloat("intensity", &e.light.intensity, 0.0f, 10.0f, "%.2f");
  changed |= ImGui::Checkbox("shadows", &e.light.shadows);
  return changed;
}

// The frame's lights: each editable, removable, and more added up to the frame's limit. The first also
// follows the light drag, so the drag's angles follow its edits.
void lightSection(Tunables& t, ViewState& view) {
  if (!ImGui::CollapsingHeader("Lights")) return;
  ImGui::TextUnformatted("the first 4 with shadows get shadow maps");
  std::optional<std::size_t> removed;
  for (std::size_t i = 0; i < t.lights.size(); ++i) {
    ImGui::PushID(int(i));
    const std::string name = "light " + std::to_string(i) + (i == 0 ? " (Shift/right drag turns it)" : "");
    if (ImGui::TreeNodeEx(name.c_str(), i == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
      if (editLight(t.lights[i], view) && i == 0) view.aimLight(view.towardLightOf(t.lights[0]));
      if (ImGui::Button("remove")) removed = i;
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  if (removed) {
    t.lights.erase(t.lights.begin() + std::ptrdiff_t(*removed));
    if (*removed == 0 && !t.lights.empty()) view.aimLight(view.towardLightOf(t.lights[0]));
  }
  if (t.lights.size() < kMaxSceneLights && ImGui::Button("add light")) {
    EditedLight rim{LightSpec{}, view.camera.target};  // a dimmer light from behind the head to start from
    rim.light.direction = glm::normalize(glm::vec3(-0.5f, 0.4f, -0.7f));
    rim.light.intensity = 1.0f;
    t.lights.push_back(rim);
    if (t.lights.size() == 1) view.aimLight(view.towardLightOf(t.lights[0]));
  }
}

void shadowSection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Shadows")) return;
  c.opacity |= ImGui::Checkbox("opacity shadow maps", &t.opacity.enabled);
  c.opacity |= ImGui::SliderFloat("strand opacity", &t.opacity.strandOpacity, 0.001f, 0.5f, "%.3f",
                                  ImGuiSliderFlags_Logarithmic);
  c.opacity |= ImGui::SliderFloat("extinction k", &t.opacity.k, 0.0f, 4.0f);
  float& bias = t.opacity.deep ? t.opacity.deepBiasSlices : t.opacity.biasSlices;
  c.opacity |= ImGui::SliderFloat(t.opacity.deep ? "bias (deep slices)" : "bias (slices)", &bias, 0.0f, 4.0f);
}

void lookSection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Look")) return;
  ImGui::SliderFloat("exposure", &t.exposure, 0.1f, 8.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
  c.look |= ImGui::SliderFloat("ambient", &t.look.ambient, 0.0f, 0.5f);
  c.look |= ImGui::SliderFloat("strand width", &t.look.strandWidth, 0.0001f, 0.003f, "%.4f");
  bool dual = t.look.scattering == render::Scattering::Dual;
  if (ImGui::Checkbox("dual scattering (physical model)", &dual)) {
    t.look.scattering = dual ? render::Scattering::Dual : render::Scattering::Single;
    c.look = true;
  }
  c.look |= ImGui::Checkbox("skin bounce", &t.look.skinBounce);
  c.look |= ImGui::Checkbox("skin indirect light", &t.look.skinIndirect);
  c.look |= ImGui::Checkbox("far side from depth", &t.look.farSideFromDepth);
}

void groomSection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Groom")) return;
  GroomSettings& g = t.groom;
  int clumps = int(g.clumpsPerTriangle);
  if (ImGui::SliderInt("clumps per triangle", &clumps, 0, 8)) {
    g.clumpsPerTriangle = std::uint32_t(clumps);
    c.groom = true;
  }
  c.groom |= ImGui::SliderFloat("clump strength", &g.clumpStrength, 0.0f, 1.0f, "%.2f");
  c.groom |= ImGui::SliderFloat("clump shape", &g.clumpShape, 0.1f, 4.0f, "%.2f");
  c.groom |= ImGui::SliderFloat("curl radius", &g.curlRadius, 0.0f, 0.02f, "%.4f");
  c.groom |= ImGui::SliderFloat("curl turns / unit", &g.curlTurns, 0.0f, 100.0f, "%.1f");
  c.groom |= ImGui::SliderFloat("curl variation", &g.curlVariation, 0.0f, 1.0f, "%.2f");
  c.groom |= ImGui::SliderFloat("frizz amplitude", &g.frizzAmplitude, 0.0f, 0.01f, "%.4f");
  c.groom |= ImGui::SliderFloat("frizz frequency", &g.frizzFrequency, 1.0f, 200.0f, "%.1f");
  c.groom |= ImGui::SliderFloat("frizz at the hairline", &g.frizzHairline, 0.0f, 10.0f, "x%.1f more");
  c.groom |= ImGui::SliderFloat("hairline width", &g.frizzHairlineWidth, 0.002f, 0.1f, "%.3f");
}

void lodSection(Tunables& t, PanelChanges& c) {
  if (!ImGui::CollapsingHeader("Level of detail")) return;
  hairpipe::LodSettings next = t.lod;
  bool changed = ImGui::Checkbox("thin strands with distance", &next.enabled);
  changed |= ImGui::SliderFloat("start distance", &next.startDistance, 0.0f, 10.0f, "%.2f");
  changed |= ImGui::SliderFloat("end distance", &next.endDistance, 0.01f, 20.0f, "%.2f");
  changed |= ImGui::SliderFloat("min fraction", &next.minFraction, 0.02f, 1.0f, "%.2f");
  next.endDistance = std::max(next.endDistance, next.startDistance + 0.01f);  // keep start < end
  if (changed) {
    t.lod = next;
    c.lod = true;
  }
}

void timingSection(const PanelStatus& s) {
  if (!ImGui::CollapsingHeader("GPU time per pass", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::Text("%s, %s raster, %u strands", s.device.c_str(), s.raster.c_str(), s.strands);
  ImGui::Text("frame %.1f ms (%.1f frames/s)", s.frameMs, s.frameMs > 0 ? 1000.0 / s.frameMs : 0.0);
  if (s.passTimes.empty()) ImGui::TextUnformatted("(no GPU timestamps on this device yet)");
  for (const auto& p : s.passTimes) ImGui::Text("%*s%-14s %7.3f ms", p.depth * 2, "", p.name.c_str(), p.milliseconds);
}
}  // namespace

PanelChanges drawPanel(Tunables& t, ViewState& view, const PanelStatus& status) {
  PanelChanges c;
  if (!view.panel) return c;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  ImGui::SetNextWindowCollapsed(status.startCollapsed, ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("hairpipe (F1 hides)", &view.panel)) {
    ImGui::End();
    return c;
  }
  timingSection(status);
  simulationSection(t, view, c);
  densitySection(t, c);
  materialSection(t, c);
  lightSection(t, view);
  shadowSection(t, c);
  lookSection(t, c);
  groomSection(t, c);
  lodSection(t, c);
  if (!status.error.empty()) ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.3f, 1.0f), "%s", status.error.c_str());
  ImGui::End();
  return c;
}
}  // namespace hp::viewer
