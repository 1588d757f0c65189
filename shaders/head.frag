#version 460
// The head: diffuse with the paper's wrap term (wrap + N.L) / (1 + wrap) (L, cone and distance scale
// from light.glsl), plus ambient; hair-coloured
// where hair grows. The direct term is shadowed by the hair (opacity maps, T = exp(-k alpha), looked up
// over a few texels: opacityAlphaSoft) and by the head itself (its depth map, head_shadow.glsl).
#include "shared/render.h"
#include "opacity_lookup.glsl"
#include "head_shadow.glsl"
#include "light.glsl"

layout(std140, binding = RENDER_BINDING_FRAME) uniform Frame { RenderFrame frame; };
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DShadow headShadowMap;
layout(location = 0) in vec3 inNormal;
layout(location = 1) in float inScalp;
layout(location = 2) in vec3 inLightUvw;
layout(location = 3) in vec4 inSliceWeights[4];
layout(location = 7) in vec3 inWorld;
layout(location = 8) in float inSlice;
layout(location = 0) out vec4 outColor;

void main() {
  vec3 N = normalize(inNormal);
  float wrap = frame.skinColor.w;
  LightSample light = sampleLight(frame.lightDirection, frame.lightPosition, frame.lightSpot, inWorld);
  float diffuse = light.scale * max((wrap + dot(N, light.L)) / (1.0 + wrap), 0.0);
  // Under the hair the scalp takes the hair's albedo, darkened as the hair's own shadow would.
  vec3 albedo = mix(frame.skinColor.rgb, 0.5 * frame.hairColor.rgb, inScalp);
  float alpha = frame.options.w != 0u
                    ? opacityAlphaDeepSoft(opacityMaps, inLightUvw, inSlice, frame.strand.w)
                    : opacityAlphaSoft(opacityMaps, inLightUvw, inSliceWeights[0], inSliceWeights[1], inSliceWeights[2],
                                       inSliceWeights[3]);
  float transmittance = exp(-frame.strand.z * alpha) *
                        headVisibility(headShadowMap, frame.headShadowViewProj, frame.headShadow, inWorld, light.L);
  outColor = vec4(albedo * (transmittance * diffuse * frame.lightRadiance.rgb / 3.14159265 + frame.hairColor.w), 1.0);
}
