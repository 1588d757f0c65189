// Shared by GLSL and C++: the environment light's spherical harmonics (docs/SHADING.md "Environment").
// The environment's radiance is projected on the 9 real SH of order <= 2 (engine/core/shading/environment_sh.h);
// the frame holds them already convolved with a clamped cosine and divided by pi, so that
// sum_i c_i Y_i(n) is the cosine-weighted mean radiance over the hemisphere around n (irradiance / pi): the
// skin's diffuse light, and for a fibre the light from the viewer's side (n) and from behind it (-n).
// envShBasis is written in the common subset of GLSL and C++, so the host's projection and the shaders'
// evaluation use the same basis, in the same order.
#ifndef HP_SHARED_ENVIRONMENT_H
#define HP_SHARED_ENVIRONMENT_H
#include "common.h"

#ifdef __cplusplus
#define HP_ENV_FN inline
namespace hp::gpu {
using vec3 = glm::vec3;
}  // namespace hp::gpu
#else
#define HP_ENV_FN
#endif

HP_BEGIN
HP_CONST(uint, ENV_SH_COEFFICIENTS, 9u)
// The clamped cosine's SH over pi, per band (Ramamoorthi and Hanrahan 2001: A_0 = pi, A_1 = 2 pi / 3,
// A_2 = pi / 4).
HP_CONST(float, ENV_COSINE_BAND0, 1.0f)
HP_CONST(float, ENV_COSINE_BAND1, 0.6666667f)
HP_CONST(float, ENV_COSINE_BAND2, 0.25f)

// Real SH basis function i at unit direction n (world axes): 0 the constant; 1-3 y, z, x; 4-8 xy, yz, 3z^2 - 1, xz,
// x^2 - y^2, with their normalisations.
HP_ENV_FN float envShBasis(uint i, vec3 n) {
  if (i == 0u) return 0.2820948f;
  if (i == 1u) return 0.4886025f * n.y;
  if (i == 2u) return 0.4886025f * n.z;
  if (i == 3u) return 0.4886025f * n.x;
  if (i == 4u) return 1.0925484f * n.x * n.y;
  if (i == 5u) return 1.0925484f * n.y * n.z;
  if (i == 6u) return 0.3153916f * (3.0f * n.z * n.z - 1.0f);
  if (i == 7u) return 1.0925484f * n.x * n.z;
  return 0.5462742f * (n.x * n.x - n.y * n.y);
}
HP_END
#endif
