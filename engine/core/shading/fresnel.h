#pragma once
// Contract: the Fresnel term of docs/THEORY.md §3.4. F(n1, n2, gamma) is the mean of the s-polarised
// reflectance for relative index n1 and the p-polarised reflectance for relative index n2, at
// incidence angle gamma (radians, sign ignored). Each polarisation is 1 under total internal
// reflection for its own index (sin gamma >= n), so F = 1 when both are.
namespace hp::shading {
double fresnelS(double n, double gamma);
double fresnelP(double n, double gamma);
double fresnel(double n1, double n2, double gamma);
}  // namespace hp::shading
