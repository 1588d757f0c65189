#pragma once
// Contract: the double-precision inverse of the `float`-mode LUT parameterisation of
// shaders/shared/marschner.h, used to place texel centres. pseudoAngle(a) is the forward map
// (a in [0, pi/2] -> [0, 1]); pseudoAngleInverse(x) its inverse; texelCentre(i, n) the value of
// x at texel i of an n-texel axis under marschnerTexelCentreCoord (i / (n - 1)).
namespace hp::shading {
double pseudoAngle(double a);
double pseudoAngleInverse(double x);
inline double texelCentre(unsigned i, unsigned n) { return double(i) / double(n - 1); }
}  // namespace hp::shading
