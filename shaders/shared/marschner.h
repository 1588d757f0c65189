// Shared by GLSL and C++ (one source of truth for the Marschner shading interface, docs/THEORY.md §3):
// - the LUT mode values, LUT resolutions and the parameterisation constants;
// - MarschnerParams, the GPU material + LUT-scale block (std140/std430-safe: 16-byte members only;
//   C++ size/offset checks live in engine/core/shading/marschner_gpu.h);
// - the texture-coordinate functions of the LUT modes. They are written in the common subset of GLSL
//   and C++ (HP_FN, float literals with an f suffix), so the CPU emulation in
//   engine/core/shading/lut_sampler.cpp computes bit-for-bit the same coordinates formula as the shader.
#ifndef HP_SHARED_MARSCHNER_H
#define HP_SHARED_MARSCHNER_H

#include "common.h"
#include "strands.h"

#ifdef __cplusplus
#include <cmath>
#define HP_FN inline
namespace hp::gpu {
using vec3 = glm::vec3;
using uvec4 = glm::uvec4;
using glm::clamp;
using glm::cos;
using glm::sin;
using std::abs;
using glm::dot;
using glm::inversesqrt;
using glm::floor;
using glm::max;
using glm::normalize;
using std::sqrt;
}  // namespace hp::gpu
#else
#define HP_FN
#endif

HP_BEGIN

// How S is evaluated (MarschnerParams.control.x, or a push constant).
HP_CONST(uint, MARSCHNER_MODE_DIRECT, 0u)     // analytic S in the shader, no textures
HP_CONST(uint, MARSCHNER_MODE_LUT_PAPER, 1u)  // the paper's two RGBA8 128x128 textures
HP_CONST(uint, MARSCHNER_MODE_LUT_FLOAT, 2u)  // three RGBA16F textures, separate lobes
HP_CONST(uint, MARSCHNER_MODE_LUT_PHYSICAL, 3u)  // the energy-conserving model (docs/THEORY.md §4), RGBA16F

// The fibre a hair shading pipeline is built for: constant_id 1 of the shaders that include hair_shading.glsl.
// HAIR_FIBRE_RUNTIME reads the model from MarschnerParams.control.x and the scattering from RenderFrame.options.z
// (every model's code in the pipeline); hairFibre() fixes both, so the compiler leaves the other models out.
// lavapipe runs both sides of a branch under a mask, so there that code costs as if it ran (the compute
// raster's shade pass: ~20 ms of 75 on the default frame, docs/PERFORMANCE.md).
HP_CONST(uint, HAIR_FIBRE_RUNTIME, 0xFFFFFFFFu)
HP_CONST(uint, HAIR_FIBRE_MODE_MASK, 0xFu)   // the MARSCHNER_MODE_* of a fixed fibre
HP_CONST(uint, HAIR_FIBRE_DUAL, 0x10u)       // with dual scattering (the physical model only)
HP_FN uint hairFibre(uint mode, bool dualScattering) {
  return mode | (dualScattering && mode == MARSCHNER_MODE_LUT_PHYSICAL ? HAIR_FIBRE_DUAL : 0u);
}

// `paper` mode: M (RGBA8) indexed by (sin theta_i, sin theta_r) * 0.5 + 0.5,
// N (RGBA8) indexed by (cos phi * 0.5 + 0.5, cos theta_d). Both square.
HP_CONST(uint, MARSCHNER_PAPER_LUT_SIZE, 128u)

// `float` mode (RGBA16F, see docs/SHADING.md for the measurements behind these numbers):
//   M  : MARSCHNER_FLOAT_M_WIDTH x 1, (M_R, M_TT, M_TRT, 0) over the signed pseudo-angle of theta_h;
//   N0 : N_WIDTH x N_HEIGHT, (N_TT.rgb, N_R); N1: same size, (N_TRT.rgb, 0);
//        u = pseudo-angle of phi/2 (0 at phi = 0, 1 at phi = pi), v = pseudo-angle of |theta_d|.
// N is NOT divided by cos^2 theta_d: the shader multiplies by 2 / (1 + cos 2 theta_d), exact and cheap.
HP_CONST(uint, MARSCHNER_FLOAT_M_WIDTH, 2048u)
HP_CONST(uint, MARSCHNER_FLOAT_N_WIDTH, 256u)
HP_CONST(uint, MARSCHNER_FLOAT_N_HEIGHT, 128u)

// `physical` mode (RGBA16F; docs/SHADING.md "physical"):
//   M  : M_SIZE x M_SIZE, (M_R, M_TT, M_TRT, M_back) over (signed pseudo-angle of theta_i, of theta_r);
//        M_back: the local back-scattering's lobe (engine/core/shading/multiple_scattering.h), dual scattering;
//        where the strands' roughness varies, M_LAYERS such squares stacked along v, one per roughness scale
//        (marschnerPhysicalMLayers below);
//   N0 : N_WIDTH x N_HEIGHT, (N_TT.rgb, N_R); N1: same size, (N_TRT + N_res).rgb;
//        u = pseudo-angle of phi/2, v = pseudo-angle of |theta_r| (the attenuations depend on theta_r).
// S = (M_R N_R + M_TT N_TT + M_TRT (N_TRT + N_res)) / cos theta_i, cos theta_i = sqrt(1 - sin^2).
HP_CONST(uint, MARSCHNER_PHYSICAL_M_SIZE, 512u)
HP_CONST(uint, MARSCHNER_PHYSICAL_N_WIDTH, 256u)
HP_CONST(uint, MARSCHNER_PHYSICAL_N_HEIGHT, 128u)
HP_CONST(float, MARSCHNER_PHYSICAL_MIN_COS_I, 1e-4f)
// Layers of M where the roughness varies: one per roughness level of the strands (shared/strands.h); 7 x 512 rows
// stay within the 4,096 every Vulkan device must sample.
HP_CONST(uint, MARSCHNER_PHYSICAL_M_LAYERS, STRAND_ROUGHNESS_LEVELS)

HP_CONST(float, MARSCHNER_INV_SQRT2, 0.70710678f)

// Multiple scattering (physical mode; engine/core/shading/multiple_scattering.h, docs/SHADING.md "Multiple
// scattering"): tables at MARSCHNER_SPREAD_ENTRIES sines of theta evenly spaced over [-1, 1], linearly
// interpolated; the forward density factor d_f of Zinke et al. 2008: 1, all the light the hair in front
// passes on (docs/SHADING.md "Multiple scattering": 0.7, Zinke's value, left blonde 13% darker against
// the corrected reference).
HP_CONST(uint, MARSCHNER_SPREAD_ENTRIES, 32u)
HP_CONST(float, MARSCHNER_FORWARD_DENSITY, 1.0f)
// Zinke's back-scattering density factor d_b: the local back-scattering term's share of A_b.
HP_CONST(float, MARSCHNER_BACK_DENSITY, 0.7f)

// GPU block: material and the factors that undo the LUT rescaling.
struct MarschnerParams {
  vec4 absorption;    // xyz = sigma_a per unit fibre radius (RGB), w = eta
  vec4 longitudinal;  // x = alpha_R, y = beta_R, z = k_G, w = w_c (radians)
  vec4 caustic;       // x = d_eta', y = dh_M, z = the strands' tilt variation (radians; strands.h strandTilt),
                      // w = their roughness variation (strands.h strandRoughness)
  vec4 mScale;        // sampled M texel * mScale = physical value (paper: per channel; float: 1)
  vec4 n0Scale;       // same for the first N texture
  vec4 n1Scale;       // same for the second N texture (float mode only)
  uvec4 control;      // x = MARSCHNER_MODE_*, yzw = 0
  vec4 skyAlbedo;     // rgb = the fibre's albedo under a uniform white sky (hp::skyAlbedo), w = 0
  vec4 skyVisibility; // physical mode: rgb = the sky a visible fibre receives with dual scattering
                      // (hp::skyVisibility), w = 0; zero otherwise
  vec4 forwardMean;   // physical mode: rgb = a_f over a uniform sky's directions (hp::meanForwardAlbedo),
                      // w = 0; zero otherwise
  // Physical mode only (zero otherwise), at sin theta = -1 + 2k / (MARSCHNER_SPREAD_ENTRIES - 1):
  vec4 forwardAlbedo[MARSCHNER_SPREAD_ENTRIES];  // rgb = a_f(theta) of the light's theta, w = 0
  vec4 meanRTT[MARSCHNER_SPREAD_ENTRIES];        // x = mean N_R, yzw = mean N_TT (rgb), at theta_r
  vec4 meanTRT[MARSCHNER_SPREAD_ENTRIES];        // rgb = mean (N_TRT + N_res), w = 0, at theta_r
  vec4 backScatter[MARSCHNER_SPREAD_ENTRIES];    // rgb = A_b (local back-scattering) of the light's theta, w = 0
  vec4 skyAlbedoFront;  // rgb = the part of skyAlbedo from the viewer's side of the fibre (incoming azimuths
                        // within 90 degrees of the outgoing one; hp::skyAlbedoOver), w = 0
};

// Pseudo-angle of a in [0, pi/2] from cos(2a): sin(a)/sqrt2 below pi/4, 1 - cos(a)/sqrt2 above.
// It is 0 at a = 0, 1/2 at pi/4, 1 at pi/2, C1, and its slope in a stays within [0.35, 0.5] (x sqrt2)
// so a texture indexed by it resolves every angle about equally, using only square roots.
HP_FN float marschnerPseudoAngle(float cos2a) {
  float s = sqrt(max(0.0f, 0.5f - 0.5f * cos2a));
  float c = sqrt(max(0.0f, 0.5f + 0.5f * cos2a));
  return cos2a >= 0.0f ? s * MARSCHNER_INV_SQRT2 : 1.0f - c * MARSCHNER_INV_SQRT2;
}

// Maps x in [0, 1] onto texel centres: x = 0 lands on the centre of texel 0, x = 1 on texel n-1, so
// the table holds both ends exactly and clamp-to-edge never extrapolates.
HP_FN float marschnerTexelCentreCoord(float x, float n) {
  return (x * (n - 1.0f) + 0.5f) / n;
}

// asin and acos to float precision from +, *, sqrt only. Vulkan lets the built-ins err by 4096 ULP
// (inherited from atan) and Mesa's are short polynomials off by up to ~1e-4 rad, which the 3.75-degree
// M_TT Gaussian turns into errors of several tenths of a percent in S (measured on lavapipe).
// Kernel: asin(x) = x + x z P(z), z = x^2, |x| <= 1/2; P is a degree-4 Chebyshev fit of
// (asin(x)/x - 1)/z made for this project (relative error 1.7e-8 on [0, 1/2]). Larger |x| go through
// asin(x) = pi/2 - 2 asin(sqrt((1 - x)/2)), where 1 - x is exact, so acos stays accurate near 0 and pi.
HP_FN float marschnerAsinKernel(float x) {
  float z = x * x;
  float p = (((0.03808502356f * z + 0.02655454221f) * z + 0.04500138007f) * z + 0.07498855073f) * z +
            0.1666667241f;
  return x + x * z * p;
}

HP_FN float marschnerAsin(float x) {
  float a = abs(x);
  if (a <= 0.5f) return marschnerAsinKernel(x);
  float r = 1.57079633f - 2.0f * marschnerAsinKernel(sqrt(max(0.0f, 0.5f - 0.5f * a)));
  return x < 0.0f ? -r : r;
}

HP_FN float marschnerAcos(float x) {
  if (abs(x) <= 0.5f) return 1.57079633f - marschnerAsinKernel(x);
  float r = 2.0f * marschnerAsinKernel(sqrt(max(0.0f, 0.5f - 0.5f * abs(x))));
  return x < 0.0f ? 3.14159265f - r : r;
}

// (sin theta_i, sin theta_r, cos phi, 0) from unit-or-not L, V, T (docs/THEORY.md §3.1).
// Degenerate azimuth (L or V parallel to T): cos phi = 0, i.e. phi = pi/2.
HP_FN vec4 marschnerAngles(vec3 L, vec3 V, vec3 T) {
  vec3 t = normalize(T);
  float si = clamp(dot(normalize(L), t), -1.0f, 1.0f);
  float sr = clamp(dot(normalize(V), t), -1.0f, 1.0f);
  vec3 lp = normalize(L) - si * t;
  vec3 vp = normalize(V) - sr * t;
  float d = dot(lp, lp) * dot(vp, vp);
  float cosPhi = d > 1e-14f ? clamp(dot(lp, vp) * inversesqrt(d), -1.0f, 1.0f) : 0.0f;
  return vec4(si, sr, cosPhi, 0.0f);
}

// `float` mode coordinates from marschnerAngles(): (M u, N u, N v, 1 / cos^2 theta_d).
// cos 2theta_h = cos(theta_i + theta_r), cos 2theta_d = cos(theta_r - theta_i): products of sines and
// cosines, no inverse trigonometry. sign(theta_h) = sign(sin theta_i + sin theta_r).
HP_FN vec4 marschnerFloatCoords(vec4 angles) {
  float si = angles.x;
  float sr = angles.y;
  float ci = sqrt(max(0.0f, 1.0f - si * si));
  float cr = sqrt(max(0.0f, 1.0f - sr * sr));
  float cos2h = ci * cr - si * sr;
  float cos2d = ci * cr + si * sr;
  float h = marschnerPseudoAngle(cos2h);
  float mx = 0.5f + 0.5f * (si + sr >= 0.0f ? h : -h);
  float mu = marschnerTexelCentreCoord(mx, float(MARSCHNER_FLOAT_M_WIDTH));
  float nu = marschnerTexelCentreCoord(marschnerPseudoAngle(angles.z), float(MARSCHNER_FLOAT_N_WIDTH));
  float nv = marschnerTexelCentreCoord(marschnerPseudoAngle(cos2d), float(MARSCHNER_FLOAT_N_HEIGHT));
  return vec4(mu, nu, nv, 2.0f / max(1.0f + cos2d, 1e-12f));
}

// Pseudo-angle of |theta| from sin(theta) (same map as marschnerPseudoAngle with cos 2a = 1 - 2 s^2,
// but taking sin a = |s| directly keeps the digits near theta = 0).
HP_FN float marschnerPseudoAngleOfSin(float s) {
  float a = abs(s);
  return a <= MARSCHNER_INV_SQRT2 ? a * MARSCHNER_INV_SQRT2
                                  : 1.0f - sqrt(max(0.0f, 1.0f - a * a)) * MARSCHNER_INV_SQRT2;
}

// The physical M texture's coordinate (u or v) of a longitudinal angle given by its sine.
HP_FN float marschnerPhysicalMCoord(float sinTheta) {
  float p = marschnerPseudoAngleOfSin(sinTheta);
  return marschnerTexelCentreCoord(0.5f + 0.5f * (sinTheta >= 0.0f ? p : -p), float(MARSCHNER_PHYSICAL_M_SIZE));
}

// `physical` mode coordinates from marschnerAngles(): (M u, M v, N u, N v), square roots only.
HP_FN vec4 marschnerPhysicalCoords(vec4 angles) {
  float pr = marschnerPseudoAngleOfSin(angles.y);
  float mu = marschnerPhysicalMCoord(angles.x);
  float mv = marschnerPhysicalMCoord(angles.y);
  float nu = marschnerTexelCentreCoord(marschnerPseudoAngle(angles.z), float(MARSCHNER_PHYSICAL_N_WIDTH));
  float nv = marschnerTexelCentreCoord(pr, float(MARSCHNER_PHYSICAL_N_HEIGHT));
  return vec4(mu, mv, nu, nv);
}

// sin(theta - delta) from sin theta (theta in [-pi/2, pi/2]) and delta's cosine and sine; an angle that would
// pass a pole stops at it (the M texture covers [-pi/2, pi/2] only).
HP_FN float marschnerShiftedSin(float sinTheta, float cosDelta, float sinDelta) {
  float c = sqrt(max(0.0f, 1.0f - sinTheta * sinTheta));
  float s = sinTheta * cosDelta - c * sinDelta;
  if (c * cosDelta + sinTheta * sinDelta < 0.0f) return s >= 0.0f ? 1.0f : -1.0f;
  return clamp(s, -1.0f, 1.0f);
}

// A strand whose cuticle tilt is alpha_R + tilt reads lobe p of the physical M texture at theta_r - k_p tilt
// (M_p = M(v_p, theta_i, theta_r - s_p), s_p = k_p alpha_R, k = 2, -1, -4; engine/core/shading/physical_terms.h):
// the texture's v coordinates for R, TT and TRT from sin theta_r and the tilt (radians).
HP_FN vec3 marschnerPhysicalTiltedMV(float sinThetaR, float tilt) {
  vec3 shift = vec3(2.0f, -1.0f, -4.0f) * tilt;
  vec3 cosShift = cos(shift), sinShift = sin(shift);
  return vec3(marschnerPhysicalMCoord(marschnerShiftedSin(sinThetaR, cosShift.x, sinShift.x)),
              marschnerPhysicalMCoord(marschnerShiftedSin(sinThetaR, cosShift.y, sinShift.y)),
              marschnerPhysicalMCoord(marschnerShiftedSin(sinThetaR, cosShift.z, sinShift.z)));
}

// Per-strand roughness (physical mode): with a roughness variation V > 0 the M texture stacks
// MARSCHNER_PHYSICAL_M_LAYERS squares along v, layer k built with beta_R x strandRoughnessOfLevel(k, V) (shared/
// strands.h: the strands' levels, evenly spaced over [1 - V, 1 + V]); a strand reads the layer of its scale,
// exactly (a scale between layers reads the nearest). With V = 0: one layer.
HP_FN uint marschnerPhysicalMLayers(float variation) { return variation > 0.0f ? MARSCHNER_PHYSICAL_M_LAYERS : 1u; }

// The layer of roughness scale s (0 without a variation).
HP_FN float marschnerPhysicalMLayer(float scale, float variation) {
  if (!(variation > 0.0f)) return 0.0f;
  float x = clamp((scale - 1.0f + variation) / (2.0f * variation), 0.0f, 1.0f) * float(MARSCHNER_PHYSICAL_M_LAYERS - 1u);
  return floor(x + 0.5f);
}

// The stacked texture's v of in-layer coordinate v (marschnerPhysicalMCoord) in layer `layer`, 1 / the layer
// count given (one division for a shading point's four lookups; with one layer, v itself).
HP_FN float marschnerPhysicalMLayerV(float v, float layer, float invLayers) { return (layer + v) * invLayers; }

// 1 / cos theta_i of the physical S, floored like the exact form.
HP_FN float marschnerPhysicalInvCosI(vec4 angles) {
  return 1.0f / max(sqrt(max(0.0f, 1.0f - angles.x * angles.x)), MARSCHNER_PHYSICAL_MIN_COS_I);
}

HP_END

#endif
