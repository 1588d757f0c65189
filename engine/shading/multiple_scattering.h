#pragma once
// Contract: the per-material tables of hairpipe's multiple-scattering term for the physical fibre model
// (REFERENCES.md §7: the global, forward part of Zinke et al. 2008's dual scattering; docs/SHADING.md
// "Multiple scattering"), in double precision, at `entries` sines of theta evenly spaced over [-1, 1]
// (the ends evaluated at +-kEdgeSine, where cos theta > 0):
//  - forwardAlbedo: the fraction of the light arriving at theta that one fibre sends on into the far
//    half of the azimuths (|phi| > pi/2), per RGB: sum_p [int M_p cos theta_i d theta_i] [int_far N_p d phi]
//    (the white furnace restricted to forward scattering; by reciprocity the same for either direction);
//  - the azimuthal means of the lobes, (1/2 pi) int N_p d phi, for R (colourless), TT and TRT + residual:
//    a fibre lit from every azimuth at once (light spread around it by the hair in front) sends
//    sum_p M_p x mean N_p toward the viewer, per unit light (what S cos theta_i is for one direction).
// Deterministic; ~2 ms for 32 entries.
#include <vector>

#include <glm/glm.hpp>

#include "engine/shading/material.h"

namespace hp {
struct MultipleScatteringTables {
  std::vector<glm::dvec3> forwardAlbedo;
  std::vector<double> meanR;
  std::vector<glm::dvec3> meanTT, meanTRT;  // TRT: with the residual p >= 3 (it shares M_TRT)
};

inline constexpr double kEdgeSine = 0.999;
MultipleScatteringTables multipleScatteringTables(const HairMaterial& m, int entries);
}  // namespace hp
