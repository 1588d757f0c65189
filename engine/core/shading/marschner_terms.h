#pragma once
// Contract: the separate factors of the exact Marschner S (docs/THEORY.md §3), double precision, for one
// material. Angles in radians; theta_h, theta_d as defined there; phi in [0, pi] (N_p is even in phi
// and in theta_d, so callers may pass either sign). lobe p: 0 = R, 1 = TT, 2 = TRT.
// N_p is the sum over ALL roots of the cubic Phi; N_TRT includes the caustic handling.
// N values are finite everywhere: at an exact caustic |dPhi/dgamma| is floored (kMinDPhi).
#include <glm/glm.hpp>

#include "engine/core/shading/material.h"

namespace hp::shading {
inline constexpr double kMinDPhi = 1e-12;

double gaussian(double beta, double x);  // g(b, x) of docs/THEORY.md §3.3
double longitudinalAlpha(int p, const HairMaterial& m);
double longitudinalBeta(int p, const HairMaterial& m);
double lobeM(int p, double thetaH, const HairMaterial& m);

double bravaisEtaPrime(double eta, double thetaD);
double bravaisEtaDoublePrime(double eta, double thetaD);

// A(p, h) per channel at the root gamma_i (h = sin gamma_i).
glm::dvec3 attenuation(int p, double gammaI, double thetaD, const HairMaterial& m);

// sum over roots of A / |2 dPhi/dh| (no caustic handling).
glm::dvec3 lobeNRaw(int p, double phi, double thetaD, const HairMaterial& m);

double lobeNR(double phi, double thetaD, const HairMaterial& m);
glm::dvec3 lobeNTT(double phi, double thetaD, const HairMaterial& m);
glm::dvec3 lobeNTRT(double phi, double thetaD, const HairMaterial& m);  // with the caustic

// The TRT caustic parameters at theta_d (exposed for tests).
struct TrtCaustic {
  double hc = 0, phic = 0, dh = 0, t = 0;
  bool causticBranch = false;  // eta' < 2
};
TrtCaustic trtCaustic(double thetaD, const HairMaterial& m);
}  // namespace hp::shading
