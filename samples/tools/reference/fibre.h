#pragma once
// Contract: the fibre scattering function S the path-traced reference evaluates, in double precision,
// in ONE place: which exact model a real-time LUT mode stands for, its name in frame exports, and S
// itself. The reference integrates L_o = int S(L, V, T) L_i cos(theta_i) d omega_i, the same convention
// as the shaders' S cos(theta_i) E for the sun (theta_i: the light's angle to the fibre's normal plane).
#include <glm/glm.hpp>

#include <string>

#include "engine/shading/lut.h"
#include "engine/shading/marschner.h"
#include "engine/shading/material.h"

namespace hp::reference {
enum class FibreModel { Marschner };  // the 2003 model of REFERENCES §3 (every LutMode of main)

inline FibreModel fibreModelOf(LutMode) { return FibreModel::Marschner; }
inline const char* fibreModelName(FibreModel) { return "marschner"; }
FibreModel parseFibreModel(const std::string& name);  // "marschner", else hp::Error

// S(L, V, T): L toward the light, V toward the eye, T the fibre tangent (unit or not, non-zero).
inline glm::dvec3 fibreS(FibreModel, const glm::dvec3& L, const glm::dvec3& V, const glm::dvec3& T,
                         const HairMaterial& m) {
  return marschnerS(L, V, T, m);
}
}  // namespace hp::reference
