#include "engine/core/shading/lut_sampler.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "shaders/shared/marschner.h"

namespace hp {
namespace {
glm::vec4 fetch(const LutTexture& t, int i, int j) {
  i = std::clamp(i, 0, int(t.width) - 1);
  j = std::clamp(j, 0, int(t.height) - 1);
  const float* p = t.texel(i, j);
  return {p[0], p[1], p[2], p[3]};
}

float weight(float f, int bits) {
  if (bits <= 0) return f;
  float steps = float(1 << bits);
  return std::nearbyint(f * steps) / steps;
}

glm::vec4 scaleOf(const LutTexture& t) { return {t.scale[0], t.scale[1], t.scale[2], t.scale[3]}; }

glm::vec3 evaluatePaper(const MarschnerLut& lut, glm::vec4 ang, const LutSamplerOptions& o) {
  const LutTexture& mt = lut.textures.at(0);
  const LutTexture& nt = lut.textures.at(1);
  glm::vec4 m = sampleBilinear(mt, ang.x * 0.5f + 0.5f, ang.y * 0.5f + 0.5f, o) * scaleOf(mt);
  glm::vec4 n = sampleBilinear(nt, ang.z * 0.5f + 0.5f, m.w, o) * scaleOf(nt);
  return (m.x * n.w + m.y * glm::vec3(n)) / std::max(m.w * m.w, 1e-6f);
}

glm::vec3 evaluateFloat(const MarschnerLut& lut, glm::vec4 ang, const LutSamplerOptions& o) {
  glm::vec4 c = gpu::marschnerFloatCoords(ang);
  glm::vec4 m = sampleBilinear(lut.textures.at(0), c.x, 0.5f, o) * scaleOf(lut.textures[0]);
  glm::vec4 n0 = sampleBilinear(lut.textures.at(1), c.y, c.z, o) * scaleOf(lut.textures[1]);
  glm::vec4 n1 = sampleBilinear(lut.textures.at(2), c.y, c.z, o) * scaleOf(lut.textures[2]);
  return (m.x * n0.w + m.y * glm::vec3(n0) + m.z * glm::vec3(n1)) * c.w;
}

// marschnerPhysicalM of shaders/marschner.glsl, unscaled; `variation`: the material's roughness variation as
// the shader reads it (MarschnerParams.caustic.w).
glm::vec4 physicalM(const LutTexture& t, glm::vec4 ang, float tilt, float roughness, float variation,
                    const LutSamplerOptions& o) {
  const float invLayers = 1.0f / float(gpu::marschnerPhysicalMLayers(variation));
  const float layer = gpu::marschnerPhysicalMLayer(roughness, variation);
  const float u = gpu::marschnerPhysicalMCoord(ang.x);
  glm::vec4 m = sampleBilinear(t, u, gpu::marschnerPhysicalMLayerV(gpu::marschnerPhysicalMCoord(ang.y), layer, invLayers), o);
  if (tilt != 0.0f) {
    const glm::vec3 v = gpu::marschnerPhysicalTiltedMV(ang.y, tilt);
    for (int p = 0; p < 3; ++p) m[p] = sampleBilinear(t, u, gpu::marschnerPhysicalMLayerV(v[p], layer, invLayers), o)[p];
  }
  return m;
}

glm::vec3 evaluatePhysical(const MarschnerLut& lut, glm::vec4 ang, const LutSamplerOptions& o, float tilt,
                           float roughness) {
  glm::vec4 c = gpu::marschnerPhysicalCoords(ang);
  const float variation = float(lut.material.roughnessVariation);
  glm::vec4 m = physicalM(lut.textures.at(0), ang, tilt, roughness, variation, o) * scaleOf(lut.textures[0]);
  glm::vec4 n0 = sampleBilinear(lut.textures.at(1), c.z, c.w, o) * scaleOf(lut.textures[1]);
  glm::vec4 n1 = sampleBilinear(lut.textures.at(2), c.z, c.w, o) * scaleOf(lut.textures[2]);
  return (m.x * n0.w + m.y * glm::vec3(n0) + m.z * glm::vec3(n1)) * gpu::marschnerPhysicalInvCosI(ang);
}
}  // namespace

glm::vec4 sampleBilinear(const LutTexture& t, float u, float v, const LutSamplerOptions& options) {
  float x = u * float(t.width) - 0.5f;
  float y = v * float(t.height) - 0.5f;
  float x0 = std::floor(x), y0 = std::floor(y);
  float fx = weight(x - x0, options.subTexelBits), fy = weight(y - y0, options.subTexelBits);
  int i = int(x0), j = int(y0);
  glm::vec4 a = glm::mix(fetch(t, i, j), fetch(t, i + 1, j), fx);
  glm::vec4 b = glm::mix(fetch(t, i, j + 1), fetch(t, i + 1, j + 1), fx);
  return glm::mix(a, b, fy);
}

glm::dvec3 evaluateLut(const MarschnerLut& lut, glm::dvec3 L, glm::dvec3 V, glm::dvec3 T,
                       const LutSamplerOptions& options, float tilt, float roughness) {
  glm::vec4 ang = gpu::marschnerAngles(glm::vec3(L), glm::vec3(V), glm::vec3(T));
  switch (lut.mode) {
    case LutMode::Paper: return glm::dvec3(evaluatePaper(lut, ang, options));
    case LutMode::Float: return glm::dvec3(evaluateFloat(lut, ang, options));
    case LutMode::Physical: return glm::dvec3(evaluatePhysical(lut, ang, options, tilt, roughness));
    case LutMode::Direct: break;
  }
  throw Error("evaluateLut: the direct mode has no lookup textures");
}
}  // namespace hp
