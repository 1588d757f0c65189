// Marschner hair shading for GLSL (docs/THEORY.md §3): ONE include used by the strand fragment shader
// and by the brdf_eval compute kernel. Interface (all take UNnormalised-OK L, V, T, non-zero):
//   vec3 marschnerDirect  (L, V, T, MarschnerParams p)                          analytic S, no textures
//   vec3 marschnerLutPaper(L, V, T, sampler2D mTex, sampler2D nTex, p)            paper, RGBA8 128x128
//   vec3 marschnerLutFloat(L, V, T, sampler2D mTex, sampler2D n0Tex, sampler2D n1Tex, p)  RGBA16F
//   vec3 marschnerLutPhysical(L, V, T, mTex, n0Tex, n1Tex, p, tilt, roughness)  the physical model (docs/THEORY.md §4), RGBA16F
//   vec3 marschnerEvaluate(mode, L, V, T, mTex, n0Tex, n1Tex, p, tilt, roughness)  switch on MARSCHNER_MODE_*
// tilt: the fibre's cuticle tilt offset from alpha_R (radians), a strand's own (shared/strands.h strandTilt);
// roughness: the scale of its beta_R (strandRoughness; 1 for none).
// Samplers: linear min/mag filter, CLAMP_TO_EDGE, normalised coordinates, one mip level. Sampled with
// textureLod(.., 0) so the same code is valid in compute shaders.
// The includer declares its MarschnerParams block as `marschner` before including this file: the
// multiple-scattering functions (physical mode) index its tables in place.
// The LUT functions mirror engine/core/shading/lut_sampler.cpp (CPU emulation) exactly; both compute their
// coordinates with the shared functions of shaders/shared/marschner.h.
//
// Deviations from the exact double-precision definition (engine/core/shading/marschner.cpp), for speed:
//  - single precision throughout; cubic roots are refined by two Newton steps (float Cardano loses
//    digits for small roots);
//  - asin/acos are marschnerAsin/marschnerAcos (shared/marschner.h), not the built-ins: Vulkan allows
//    the built-ins 4096 ULP and lavapipe's are off by ~1e-4 rad, which made the device's direct S
//    miss by p99 0.31% (now 0.0002%); gamma_t needs only its cosine, so it is never formed;
//  - marschnerDirect takes phi from the vectors (marschnerAzimuth), not acos(cos phi), which loses
//    half the float digits near phi = pi where N_R ~ cos(phi/2) -> 0 (device max error 0.47% -> 0.02%);
//  - cos theta_d is floored at 1e-4 (exact: 1e-6) and |dPhi/dgamma| at 1e-6 (exact: 1e-12), so the
//    integrable singularities at |theta_d| -> 90 deg and at the cubic's own caustic saturate earlier;
//  - N_R uses its closed form F(eta', eta'', -phi/2) cos(phi/2) / 4 instead of the root sum (equal:
//    the only other R root, gamma = pi/2 at phi = pi, contributes 0).
//
// The analytic part (up to marschnerDirect) avoids swizzles so tests/shading/glsl_port_test.cpp can
// compile it as C++ in double precision (MARSCHNER_GLSL_AS_CPP) and check its logic against the
// exact reference; precision on the GPU is checked by the brdf_eval kernel.
#ifndef HP_MARSCHNER_GLSL
#define HP_MARSCHNER_GLSL

#ifndef MARSCHNER_GLSL_AS_CPP
#include "shared/marschner.h"
#endif

#ifdef MARSCHNER_GLSL_AS_CPP
// The C++ port checks the logic in double, with the exact inverse trigonometry.
float marschnerAsin(float x) { return asin(x); }
float marschnerAcos(float x) { return acos(x); }
#endif

const float MARSCHNER_PI = 3.14159265358979;
const float MARSCHNER_HALF_PI = 1.57079632679490;
const float MARSCHNER_TWO_PI = 6.28318530717959;
const float MARSCHNER_SQRT_2PI = 2.50662827463100;

float marschnerGaussian(float b, float x) {
  return exp(-x * x / (2.0 * b * b)) / (b * MARSCHNER_SQRT_2PI);
}

// Fresnel of docs/THEORY.md §3.4: mean of s (index n1) and p (index n2) reflectance, 1 under TIR.
float marschnerFresnelS(float n, float cosI) {
  float sinT2 = (1.0 - cosI * cosI) / (n * n);
  if (sinT2 >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sinT2);
  float r = (cosI - n * cosT) / (cosI + n * cosT);
  return r * r;
}

float marschnerFresnelP(float n, float cosI) {
  float sinT2 = (1.0 - cosI * cosI) / (n * n);
  if (sinT2 >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sinT2);
  float r = (n * cosI - cosT) / (n * cosI + cosT);
  return r * r;
}

// c = |cos gamma|.
float marschnerFresnelCos(float n1, float n2, float c) {
  return 0.5 * (marschnerFresnelS(n1, c) + marschnerFresnelP(n2, c));
}

float marschnerFresnel(float n1, float n2, float gamma) {
  return marschnerFresnelCos(n1, n2, abs(cos(gamma)));
}

// Per-theta_d quantities shared by every lobe.
struct MarschnerFiber {
  float etaP;       // eta'
  float etaPP;      // eta''
  float cosThetaT;  // cos of the refracted longitudinal angle
  vec3 sigma;       // sigma_a per unit radius
};

// A(p, h) at the root gamma_i.
vec3 marschnerAttenuation(int p, float gammaI, MarschnerFiber f) {
  float fr = marschnerFresnel(f.etaP, f.etaPP, gammaI);
  if (p == 0) return vec3(fr);
  // Only cos gamma_t is needed: no inverse trigonometry (see marschnerAsin in shared/marschner.h).
  float sinGammaT = clamp(sin(gammaI) / f.etaP, -1.0, 1.0);
  float cosGammaT = sqrt(1.0 - sinGammaT * sinGammaT);
  vec3 t = exp(-2.0 * f.sigma / f.cosThetaT * cosGammaT);
  vec3 a = (1.0 - fr) * (1.0 - fr) * t;
  if (p == 2) a *= marschnerFresnelCos(1.0 / f.etaP, 1.0 / f.etaPP, cosGammaT) * t;
  return a;
}

float marschnerCbrt(float x) { return sign(x) * pow(abs(x), 1.0 / 3.0); }

// Real roots of x^3 + P x + Q = 0; returns the count (1 or 3).
int marschnerSolveCubic(float P, float Q, out float r[3]) {
  float disc = 0.25 * Q * Q + P * P * P / 27.0;
  if (disc > 0.0 || P >= 0.0) {
    float s = sqrt(max(disc, 0.0));
    r[0] = marschnerCbrt(-0.5 * Q + s) + marschnerCbrt(-0.5 * Q - s);
    return 1;
  }
  float m = 2.0 * sqrt(-P / 3.0);
  float th = marschnerAcos(clamp(3.0 * Q / (P * m), -1.0, 1.0)) / 3.0;
  for (int j = 0; j < 3; ++j) r[j] = m * cos(th - MARSCHNER_TWO_PI * float(j) / 3.0);
  return 3;
}

// N_p without the caustic: sum over all roots gamma of Phi(p, gamma) = phi + 2 pi k of
// A(p, h) / |2 dPhi/dh| = A cos(gamma) / (2 |dPhi/dgamma|).
vec3 marschnerNRaw(int p, float phi, MarschnerFiber f) {
  float c = marschnerAsin(1.0 / f.etaP);
  float a = 6.0 * float(p) * c / MARSCHNER_PI - 2.0;
  float b = 8.0 * float(p) * c / (MARSCHNER_PI * MARSCHNER_PI * MARSCHNER_PI);
  float h = MARSCHNER_HALF_PI;
  float reach = abs(a * h - b * h * h * h);  // Phi - p pi is odd: its range is [-reach, reach]
  if (a > 0.0 && b > 0.0) {
    float g = sqrt(a / (3.0 * b));
    if (g < h) reach = max(reach, a * g - b * g * g * g);
  }
  float base = float(p) * MARSCHNER_PI;
  int kMin = int(ceil((base - reach - phi) / MARSCHNER_TWO_PI));
  int kMax = int(floor((base + reach - phi) / MARSCHNER_TWO_PI));
  vec3 sum = vec3(0.0);
  for (int k = kMin; k <= kMax; ++k) {
    float rhs = phi + MARSCHNER_TWO_PI * float(k) - base;  // a g - b g^3 = rhs
    float r[3];
    int n = 1;
    if (p == 0) r[0] = rhs / a;
    else n = marschnerSolveCubic(-a / b, rhs / b, r);
    for (int i = 0; i < n; ++i) {
      float g = r[i];
      for (int it = 0; it < 2; ++it) {
        float d = a - 3.0 * b * g * g;
        if (abs(d) > 1e-6) g -= (a * g - b * g * g * g - rhs) / d;
      }
      if (abs(g) > h) continue;
      float dPhi = max(abs(a - 3.0 * b * g * g), 1e-6);
      sum += marschnerAttenuation(p, g, f) * cos(g) / (2.0 * dPhi);
    }
  }
  return sum;
}

float marschnerWrapPi(float x) {
  return x - MARSCHNER_TWO_PI * floor((x + MARSCHNER_PI) / MARSCHNER_TWO_PI);
}

// N_TRT with the caustic handling of docs/THEORY.md §3.5.
vec3 marschnerNTRT(float phi, MarschnerFiber f, MarschnerParams prm) {
  float kG = prm.longitudinal.z, wc = prm.longitudinal.w;
  float dEta = prm.caustic.x, dhM = prm.caustic.y;
  float hc = 0.0, phic = 0.0, dh = dhM, t;
  if (f.etaP < 2.0) {
    hc = sqrt((4.0 - f.etaP * f.etaP) / 3.0);
    phic = 4.0 * marschnerAsin(hc / f.etaP) - 2.0 * marschnerAsin(hc) + MARSCHNER_TWO_PI;
    float e2 = f.etaP * f.etaP - hc * hc, o2 = 1.0 - hc * hc;
    float d2 = abs(4.0 * hc / (e2 * sqrt(e2)) - 2.0 * hc / (o2 * sqrt(o2)));
    dh = d2 > 0.0 ? min(dhM, 2.0 * sqrt(2.0 * wc / d2)) : dhM;
    t = 1.0;
  } else {
    t = 1.0 - smoothstep(2.0, 2.0 + dEta, f.etaP);
  }
  float dm = marschnerWrapPi(phi - phic), dp = marschnerWrapPi(phi + phic);
  float rm = exp(-dm * dm / (2.0 * wc * wc));  // g(wc, x) / g(wc, 0)
  float rp = exp(-dp * dp / (2.0 * wc * wc));
  vec3 n = marschnerNRaw(2, phi, f) * (1.0 - t * rm) * (1.0 - t * rp);
  vec3 glint = marschnerAttenuation(2, marschnerAsin(hc), f) * (t * kG * dh * (rm + rp) / (wc * MARSCHNER_SQRT_2PI));
  return n + glint;
}

// phi in [0, pi] from the vectors. acos(cos phi) loses half the digits near phi = 0 and pi (1 + cos phi
// cancels), which showed on the device as 0.5% errors of N_R ~ cos(phi/2) near phi = pi. The unit
// projections l, v give |l - v| = 2 sin(phi/2) and |l + v| = 2 cos(phi/2); the smaller is well
// conditioned. Degenerate azimuth: phi = pi/2, the rule of marschnerAngles (same test, same threshold).
float marschnerAzimuth(vec3 L, vec3 V, vec3 T) {
  vec3 t = normalize(T);
  vec3 l = normalize(L);
  vec3 v = normalize(V);
  vec3 lp = l - clamp(dot(l, t), -1.0, 1.0) * t;
  vec3 vp = v - clamp(dot(v, t), -1.0, 1.0) * t;
  if (!(dot(lp, lp) * dot(vp, vp) > 1e-14)) return MARSCHNER_HALF_PI;
  lp = normalize(lp);
  vp = normalize(vp);
  float s = length(lp - vp), c = length(lp + vp);
  return s < c ? 2.0 * marschnerAsin(0.5 * s) : MARSCHNER_PI - 2.0 * marschnerAsin(0.5 * c);
}

vec3 marschnerDirect(vec3 L, vec3 V, vec3 T, MarschnerParams prm) {
  vec4 ang = marschnerAngles(L, V, T);
  float ti = marschnerAsin(ang.x), tr = marschnerAsin(ang.y);
  float thetaH = 0.5 * (ti + tr), thetaD = 0.5 * (tr - ti);
  float phi = marschnerAzimuth(L, V, T);
  float eta = prm.absorption.w;
  float cosD = max(cos(thetaD), 1e-4), sinD = sin(thetaD);
  float root = sqrt(eta * eta - sinD * sinD);
  float sinT = sinD / eta;
  MarschnerFiber f = MarschnerFiber(root / cosD, eta * eta * cosD / root, sqrt(1.0 - sinT * sinT),
                                    vec3(prm.absorption));
  float alpha = prm.longitudinal.x, beta = prm.longitudinal.y;
  float mR = marschnerGaussian(beta, thetaH - alpha);
  float mTT = marschnerGaussian(0.5 * beta, thetaH + 0.5 * alpha);
  float mTRT = marschnerGaussian(2.0 * beta, thetaH + 1.5 * alpha);
  float nR = marschnerFresnel(f.etaP, f.etaPP, 0.5 * phi) * cos(0.5 * phi) * 0.25;
  vec3 nTT = marschnerNRaw(1, phi, f);
  vec3 nTRT = marschnerNTRT(phi, f, prm);
  return (mR * nR + mTT * nTT + mTRT * nTRT) / (cosD * cosD);
}

#ifndef MARSCHNER_GLSL_AS_CPP
// The paper's form: m = M(sin theta_i, sin theta_r) = (M_R, M_TT, M_TRT, cos theta_d), then
// n = N(cos phi, cos theta_d) = (N_TT + N_TRT, N_R); M_TT stands in for M_TRT (paper's assumption).
vec3 marschnerLutPaper(vec3 L, vec3 V, vec3 T, sampler2D mTex, sampler2D nTex, MarschnerParams prm) {
  vec4 ang = marschnerAngles(L, V, T);
  vec4 m = textureLod(mTex, ang.xy * 0.5 + 0.5, 0.0) * prm.mScale;
  vec4 n = textureLod(nTex, vec2(ang.z * 0.5 + 0.5, m.w), 0.0) * prm.n0Scale;
  return (m.x * n.w + m.y * n.xyz) / max(m.w * m.w, 1e-6);
}

// Float LUTs: M over the pseudo-angle of theta_h, N0 = (N_TT, N_R), N1 = (N_TRT, -) over
// (pseudo-angle of phi/2, of |theta_d|); 1 / cos^2 theta_d computed exactly.
vec3 marschnerLutFloat(vec3 L, vec3 V, vec3 T, sampler2D mTex, sampler2D n0Tex, sampler2D n1Tex,
                       MarschnerParams prm) {
  vec4 c = marschnerFloatCoords(marschnerAngles(L, V, T));
  vec4 m = textureLod(mTex, vec2(c.x, 0.5), 0.0) * prm.mScale;
  vec4 n0 = textureLod(n0Tex, c.yz, 0.0) * prm.n0Scale;
  vec4 n1 = textureLod(n1Tex, c.yz, 0.0) * prm.n1Scale;
  return (m.x * n0.w + m.y * n0.xyz + m.z * n1.xyz) * c.w;
}

// The physical model's longitudinal terms (M_R, M_TT, M_TRT, M_back) at marschnerAngles() `ang` for a fibre
// whose cuticle tilt is alpha_R + tilt (radians; a strand's variation, shared/strands.h strandTilt) and whose
// beta_R is scaled by `roughness` (strandRoughness): with a tilt, each lobe is read at its own shifted theta_r
// (marschnerPhysicalTiltedMV), M_back where it lies; with a roughness variation, all from the layer of the
// strand's scale (shared/marschner.h marschnerPhysicalMLayers).
vec4 marschnerPhysicalM(vec4 ang, float tilt, float roughness, sampler2D mTex) {
  float variation = marschner.caustic.w;
  float invLayers = 1.0 / float(marschnerPhysicalMLayers(variation));
  float layer = marschnerPhysicalMLayer(roughness, variation);
  float u = marschnerPhysicalMCoord(ang.x);
  vec4 m = textureLod(mTex, vec2(u, marschnerPhysicalMLayerV(marschnerPhysicalMCoord(ang.y), layer, invLayers)), 0.0);
  if (tilt != 0.0) {
    vec3 v = marschnerPhysicalTiltedMV(ang.y, tilt);
    m.x = textureLod(mTex, vec2(u, marschnerPhysicalMLayerV(v.x, layer, invLayers)), 0.0).x;
    m.y = textureLod(mTex, vec2(u, marschnerPhysicalMLayerV(v.y, layer, invLayers)), 0.0).y;
    m.z = textureLod(mTex, vec2(u, marschnerPhysicalMLayerV(v.z, layer, invLayers)), 0.0).z;
  }
  return m * marschner.mScale;
}

// The physical model (docs/THEORY.md §4) from its longitudinal terms m (marschnerPhysicalM): N0 = (N_TT, N_R),
// N1 = N_TRT + N_res over (phi/2, |theta_r|); S = (M_R N_R + M_TT N_TT + M_TRT N1) / cos theta_i.
vec3 marschnerPhysicalS(vec4 ang, vec4 m, sampler2D n0Tex, sampler2D n1Tex) {
  vec4 c = marschnerPhysicalCoords(ang);
  vec4 n0 = textureLod(n0Tex, c.zw, 0.0) * marschner.n0Scale;
  vec4 n1 = textureLod(n1Tex, c.zw, 0.0) * marschner.n1Scale;
  return (m.x * n0.w + m.y * n0.xyz + m.z * n1.xyz) * marschnerPhysicalInvCosI(ang);
}

vec3 marschnerLutPhysical(vec3 L, vec3 V, vec3 T, sampler2D mTex, sampler2D n0Tex, sampler2D n1Tex,
                          MarschnerParams prm, float tilt, float roughness) {
  vec4 ang = marschnerAngles(L, V, T);
  return marschnerPhysicalS(ang, marschnerPhysicalM(ang, tilt, roughness, mTex), n0Tex, n1Tex);
}

// Multiple scattering (physical mode; docs/SHADING.md "Multiple scattering"). The spread tables hold
// MARSCHNER_SPREAD_ENTRIES values over sin theta in [-1, 1]: entry x and x + 1, mixed by y. The functions
// that index them read the includer's block `marschner` in place: given a MarschnerParams by value, a
// compiler may copy the whole struct (2 KiB of tables) per call to index it, which made lavapipe's shade
// pass 2.7x slower (docs/PERFORMANCE.md "The shade pass").
vec2 marschnerSpreadCoord(float sinTheta) {
  float x = clamp(sinTheta * 0.5 + 0.5, 0.0, 1.0) * float(MARSCHNER_SPREAD_ENTRIES - 1u);
  float i = min(floor(x), float(MARSCHNER_SPREAD_ENTRIES - 2u));
  return vec2(i, x - i);
}

// The fraction a_f of light arriving at sin theta that one fibre scatters on forward (|phi| > pi/2).
vec3 marschnerForwardAlbedo(float sinTheta) {
  vec2 c = marschnerSpreadCoord(sinTheta);
  uint i = uint(c.x);
  return mix(marschner.forwardAlbedo[i].rgb, marschner.forwardAlbedo[i + 1u].rgb, c.y);
}

// Multiple scattering's response (physical mode; the counterpart of S cos theta_i), per unit light that
// arrives from L's theta, `lit` of it unscattered from L's azimuth and `spread` of it spread around the
// fibre by the hair in front (Zinke's T_f; docs/SHADING.md "Multiple scattering", "Local back-scattering"):
//  - the spread light: sum_p M_p(theta_i, theta_r) x the mean of N_p over phi;
//  - the light the hair around scatters back (A_b of the light's theta): d_b A_b M_back(theta_i, theta_r)
//    x (1 + cos phi) / 2 pi for the unscattered light (the near half of the azimuths, smoothly; unit
//    area) and 1 / 2 pi for the spread light. M_back is the M texture's fourth channel.
// ang: marschnerAngles(L, V, T); m: marschnerPhysicalM there.
vec3 marschnerPhysicalMultipleResponse(vec4 ang, vec4 m, float lit, vec3 spread) {
  vec2 r = marschnerSpreadCoord(ang.y);
  uint j = uint(r.x);
  vec4 rtt = mix(marschner.meanRTT[j], marschner.meanRTT[j + 1u], r.y);
  vec3 trt = mix(marschner.meanTRT[j].rgb, marschner.meanTRT[j + 1u].rgb, r.y);
  vec3 forward = (m.x * rtt.x + m.y * rtt.yzw + m.z * trt) * spread;
  vec2 c = marschnerSpreadCoord(ang.x);
  uint i = uint(c.x);
  vec3 A = mix(marschner.backScatter[i].rgb, marschner.backScatter[i + 1u].rgb, c.y);
  vec3 back = MARSCHNER_BACK_DENSITY * A * m.w * (lit * (1.0 + ang.z) + spread) / MARSCHNER_TWO_PI;
  return forward + back;
}

// The ONE shading entry point of every hair shading path but the physical mode's with dual scattering, which
// shares its longitudinal terms with the multiple scattering (hair_shading.glsl). mode = MARSCHNER_MODE_*;
// paper mode reads mTex and n0Tex only, direct none. tilt: the fibre's cuticle tilt offset (radians), taken by
// the physical and direct modes; the paper and float tables are of one tilt and ignore it.
vec3 marschnerEvaluate(uint mode, vec3 L, vec3 V, vec3 T, sampler2D mTex, sampler2D n0Tex,
                       sampler2D n1Tex, MarschnerParams prm, float tilt, float roughness) {
  if (mode == MARSCHNER_MODE_LUT_PHYSICAL)
    return marschnerLutPhysical(L, V, T, mTex, n0Tex, n1Tex, prm, tilt, roughness);
  if (mode == MARSCHNER_MODE_LUT_FLOAT) return marschnerLutFloat(L, V, T, mTex, n0Tex, n1Tex, prm);
  if (mode == MARSCHNER_MODE_LUT_PAPER) return marschnerLutPaper(L, V, T, mTex, n0Tex, prm);
  prm.longitudinal.x += tilt;
  prm.longitudinal.y *= roughness;
  return marschnerDirect(L, V, T, prm);
}
#endif  // MARSCHNER_GLSL_AS_CPP

#endif
