#pragma once
// Contract: the factors of the energy-conserving fibre model (docs/THEORY.md §4: d'Eon et al. 2011
// longitudinal terms, Chiang et al. 2016 / pbrt-v3 attenuations and residual), double precision.
// Conventions (docs/SHADING.md "physical"):
//  - theta_i, theta_r are the longitudinal angles of L and V (sin = dot with the unit tangent), phi the
//    azimuth in [0, pi]; lobe p: 0 = R, 1 = TT, 2 = TRT, 3 = residual (all p >= 3 lumped).
//  - The attenuations depend on the OUTGOING angle theta_r (not theta_d): with the M_p normalised over
//    theta_i for every theta_r, the white furnace is then exactly sum_p (1/2) int A_p dh = 1.
//  - Cuticle tilt: M_p(theta_i, theta_r) = M(v_p, theta_i, theta_r - s_p), s_R = 2 alpha_R,
//    s_TT = -alpha_R, s_TRT = s_res = -4 alpha_R (pbrt-v3's magnitudes, oriented so that R peaks at
//    theta_h = alpha_R as in the paper's model). Variances v_R = 4 beta_R^2, v_TT = v_R / 4,
//    v_TRT = v_res = 4 v_R (beta_p = std. dev. of theta_h <-> v_p = 4 beta_p^2).
//  - Azimuthal lobe D: a Gaussian of std. dev. material.betaN wrapped on the circle (unit area on
//    [-pi, pi]); N_p(phi) = 1/2 int_{-1}^{1} A_p(h) D(phi - Phi(p, h)) dh, Phi = 2 p gamma_t - 2 gamma_o + p pi;
//    the residual is uniform: N_res = (1/2 int A_res dh) / (2 pi).
#include <array>

#include <glm/glm.hpp>

#include "engine/core/shading/material.h"

namespace hp::shading {
inline constexpr int kPhysicalLobes = 4;
inline constexpr double kPhysicalMinCos = 1e-6;  // floor of cos theta (poles)
// Panels of the h integral of N_p (8 Gauss-Legendre nodes each) over gamma_o in [-pi/2, pi/2], node
// weights 0.5 w cos(gamma_o) (h = sin gamma_o uniform on [-1, 1]); convergence is checked by the white
// furnace in tests/shading/physical_test.cpp, which needs every lobe exact.
inline constexpr int kPhysicalAzimuthPanels = 32;

double logBesselI0(double x);  // log I0(x), x >= 0, finite for any x
// d'Eon's M(v, theta_i, theta_r) from the sines and cosines (cosines >= 0); integrates to 1 against
// cos theta_i d theta_i over [-pi/2, pi/2] for every theta_r.
double deonM(double v, double sinI, double cosI, double sinR, double cosR);

double physicalVariance(int p, const HairMaterial& m);
double physicalShift(int p, const HairMaterial& m);
double physicalM(int p, double sinThetaI, double sinThetaR, const HairMaterial& m);
// physicalM of one lobe at one theta_r for many theta_i (what depends on theta_r alone computed once): out[k] at
// sinThetaI[k], the same values.
void physicalMRow(int p, double sinThetaR, const HairMaterial& m, const double* sinThetaI, int count, double* out);

// Everything A_p(h) needs that depends on the outgoing angle only.
struct PhysicalFibre {
  double eta = 1.55, etaPrime = 1.55;  // Bravais eta' at theta_r
  double cosTheta = 1, cosThetaT = 1;  // cos theta_r, cos of its refracted angle
  glm::dvec3 sigma{0.0};
};
PhysicalFibre physicalFibre(double sinThetaR, const HairMaterial& m);

struct PhysicalAttenuation {
  std::array<glm::dvec3, kPhysicalLobes> a;  // A_R, A_TT, A_TRT, A_res
  double gammaO = 0, gammaT = 0;
};
PhysicalAttenuation physicalAttenuation(double h, const PhysicalFibre& f);

double physicalPhi(int p, double gammaO, double gammaT);
double wrappedGaussian(double sigma, double x);  // unit area over one period

// N_R (colourless), N_TT, N_TRT, N_res at (phi, theta_r); N_res already includes the 1/(2 pi).
struct PhysicalN {
  double r = 0;
  glm::dvec3 tt{0.0}, trt{0.0}, res{0.0};
};
PhysicalN physicalN(double phi, double sinThetaR, const HairMaterial& m);
// The same for many phi at one theta_r (the attenuations at the quadrature nodes are shared): out[k] at phis[k].
void physicalNRow(double sinThetaR, const HairMaterial& m, const double* phis, int count, PhysicalN* out);
// int N_p d phi over |phi| in [phiLo, phiHi] (both signs: N is even in phi), per lobe, by composite
// Gauss-Legendre with `panels` panels (one physicalNRow).
PhysicalN physicalNIntegral(double sinThetaR, const HairMaterial& m, double phiLo, double phiHi, int panels);
// (1/2) int A_p dh per lobe: the fraction of light each lobe carries (sums to 1 without absorption).
std::array<glm::dvec3, kPhysicalLobes> physicalLobeEnergy(double sinThetaR, const HairMaterial& m);
}  // namespace hp::shading
