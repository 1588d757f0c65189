// The radiance a hair fibre sends toward the camera (docs/THEORY.md §3-6), GLSL only, shared by the graphics
// strand shader (strands.frag, per fragment) and the compute rasterizer (raster_shade.comp, per vertex):
// S(L, V, T) cos(theta_i) x light x transmittance [+ the light the hair in front scattered forward and the
// light the hair around scatters back, dual scattering] + sky albedo x (ambient x RENDER_HAIR_SKY_VISIBILITY
// + `bounce`), times the strand's lightness variation. `bounce` is the mean radiance the skin sends the point
// (head_bounce.glsl; vec3(0) without it).
// The includer declares `frame` (RenderFrame), `marschner` (MarschnerParams), the LUT samplers
// lutM, lutN0, lutN1 and `headShadowMap` (the head's depth map) before including this file; `alpha` is
// the opacity-map lookup at the point. The transmittance is the hair's (opacity maps) times the head's.
#ifndef HP_HAIR_SHADING_GLSL
#define HP_HAIR_SHADING_GLSL
#include "head_shadow.glsl"
#include "light.glsl"

vec3 hairRadiance(vec3 world, vec3 tangent, float colorScale, float alpha, vec3 bounce) {
  vec3 T = normalize(tangent);
  LightSample light = sampleLight(frame.lightDirection, frame.lightPosition, frame.lightSpot, world);
  vec3 L = light.L;
  vec3 V = normalize(frame.cameraPosition.xyz - world);
  vec3 S = marschnerEvaluate(marschner.control.x, L, V, T, lutM, lutN0, lutN1, marschner);
  float sinThetaI = clamp(dot(L, T), -1.0, 1.0);
  float cosThetaI = sqrt(1.0 - sinThetaI * sinThetaI);
  float tau = frame.strand.z * alpha;  // optical depth toward the light: the mean number of fibres crossed
  float head = headVisibility(headShadowMap, frame.headShadowViewProj, frame.headShadow, world, L);
  vec3 incident = frame.lightRadiance.rgb * (light.scale * head);
  vec3 direct = S * cosThetaI * incident * exp(-tau);
  // Multiple scattering (dual; docs/SHADING.md "Multiple scattering"): of the light that hits N fibres on
  // its way (N Poisson with mean tau), a fraction d_f a_f^N goes on forward, spread around the fibre:
  // E[a_f^N; N >= 1] = exp(-tau (1 - a_f)) - exp(-tau). The hair around the fibre scatters back A_b of
  // both the unscattered light and that spread light (local back-scattering).
  if (frame.options.z == RENDER_SCATTERING_DUAL && marschner.control.x == MARSCHNER_MODE_LUT_PHYSICAL) {
    vec3 af = marschnerForwardAlbedo(sinThetaI, marschner);
    vec3 spread = MARSCHNER_FORWARD_DENSITY * max(exp(-tau * (1.0 - af)) - exp(-tau), vec3(0.0));
    direct += marschnerPhysicalMultipleResponse(L, V, T, exp(-tau), spread, lutM, marschner) * incident;
  }
  // The ambient is a uniform white sky: an unoccluded fibre returns the model's sky albedo times its
  // radiance, a fibre of a head of hair the mean visible fraction of it (shared/render.h).
  // The skin's bounce is treated the same way: the fibre's response to it is the sky albedo times its mean.
  vec3 ambient = marschner.skyAlbedo.rgb * (frame.hairColor.w * RENDER_HAIR_SKY_VISIBILITY + bounce);
  return (direct + ambient) * colorScale;
}
#endif
