#version 460
// Hair shading (REFERENCES.md §3-4): radiance = S(L, V, T) cos(theta_i) x light x transmittance, plus
// a small ambient term, times the strand's lightness variation. Alpha is the ribbon's pixel coverage
// (alpha-to-coverage with MSAA). Transmittance T = exp(-k alpha) from the opacity maps with the
// per-vertex slice weights (opacity_lookup.glsl); the ambient term is not shadowed.
#include "shared/render.h"
#include "shared/marschner.h"
#include "marschner.glsl"
#include "opacity_lookup.glsl"

layout(std140, binding = RENDER_BINDING_FRAME) uniform Frame { RenderFrame frame; };
layout(std140, binding = RENDER_BINDING_MARSCHNER) uniform Marschner { MarschnerParams marschner; };
layout(binding = RENDER_BINDING_LUT_M) uniform sampler2D lutM;
layout(binding = RENDER_BINDING_LUT_N0) uniform sampler2D lutN0;
layout(binding = RENDER_BINDING_LUT_N1) uniform sampler2D lutN1;
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inTangent;
layout(location = 2) in float inCoverage;
layout(location = 3) in float inColorScale;
layout(location = 4) in vec2 inLightUv;
layout(location = 5) in vec4 inSliceWeights[4];
layout(location = 0) out vec4 outColor;

void main() {
  vec3 T = normalize(inTangent);
  vec3 L = frame.lightDirection.xyz;
  vec3 V = normalize(frame.cameraPosition.xyz - inWorld);
  vec3 S = marschnerEvaluate(marschner.control.x, L, V, T, lutM, lutN0, lutN1, marschner);
  float sinThetaI = clamp(dot(L, T), -1.0, 1.0);
  float cosThetaI = sqrt(1.0 - sinThetaI * sinThetaI);
  float alpha = opacityAlpha(opacityMaps, inLightUv, inSliceWeights[0], inSliceWeights[1], inSliceWeights[2],
                             inSliceWeights[3]);
  float transmittance = exp(-frame.strand.z * alpha);
  vec3 direct = S * cosThetaI * frame.lightRadiance.rgb * transmittance;
  vec3 ambient = frame.hairColor.rgb * frame.hairColor.w;
  outColor = vec4((direct + ambient) * inColorScale, inCoverage);
}
