#pragma once
// Contract: the fibre scattering function S the path-traced reference evaluates, in double precision,
// in ONE place: which exact model a real-time LUT mode stands for (engine/core/shading/fibre_model.h: the
// energy-conserving `physical` model, or the paper's `marschner` behind float/paper/direct), its name
// in frame exports, and S itself. The reference integrates L_o = int S(L, V, T) L_i cos(theta_i) d omega_i,
// the shaders' convention (S cos(theta_i) E for the sun; theta_i: the light's angle to the normal plane).
#include <glm/glm.hpp>

#include <string>

#include "engine/core/shading/fibre_model.h"

namespace hp::reference {
using hp::FibreModel;
using hp::fibreModelOf;
const char* fibreModelName(FibreModel model);       // "physical" | "marschner"
FibreModel parseFibreModel(const std::string& name);  // the names above, else hp::Error

// S(L, V, T): L toward the light, V toward the eye, T the fibre tangent (unit or not, non-zero).
inline glm::dvec3 fibreS(FibreModel model, const glm::dvec3& L, const glm::dvec3& V, const glm::dvec3& T,
                         const HairMaterial& m) {
  return exactS(model, L, V, T, m);
}
}  // namespace hp::reference
