#version 460
// The head bounce map's texels (compute/shadows/head_bounce_map.h): each is a small Lambertian emitter for the
// gather of head_bounce.glsl. Flux = albedo x E x T_hair x A_perp: the skin's radiosity albedo E cos(theta) T
// times the texel's area on the surface A_perp / cos(theta); A_perp (the texel's area across the light) comes
// from the derivatives of the world position, so ortho and spot maps need no special case. alpha is the
// hair's opacity-map value at the skin (the gather takes the hair between a fibre and the skin from it).
// The albedo is head.frag's (skin, or the hair-coloured scalp); no wrap term: the reference's skin is
// Lambertian. Only the surface nearest the light is kept (depth test), so the head shadows itself here.
#include "shared/render.h"
#include "head_bounce_encoding.glsl"

layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };
layout(location = 0) in vec3 inNormal;
layout(location = 1) in float inScalp;
layout(location = 2) in vec3 inWorld;
layout(location = 0) out vec4 outFlux;      // rgb flux, a = 1 + alpha (0: no skin in this texel)
layout(location = 1) out vec4 outPosition;  // xyz world, w = the unit normal (bounceEncodeNormal)
#include "frame_shadows.glsl"

void main() {
  FrameLight light = frame.lights[frame.lightCount.y];  // the light of shadow slot 0
  LightSample ls = sampleLight(light, inWorld);
  vec3 albedo = mix(frame.skinColor.rgb, 0.5 * frame.hairColor.rgb, inScalp);
  float alpha = frameOpacityAlpha(0u, inWorld, true);
  float areaAcross = abs(dot(cross(dFdx(inWorld), dFdy(inWorld)), ls.L));
  vec3 E = light.radiance.rgb * ls.scale;
  outFlux = vec4(albedo * E * hairTransmittance(frame.strand.z * alpha) * areaAcross, 1.0 + alpha);
  outPosition = vec4(inWorld, bounceEncodeNormal(normalize(inNormal)));
}
