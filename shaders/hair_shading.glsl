// The radiance a hair fibre sends toward the camera (docs/THEORY.md §3-6), GLSL only, shared by the graphics
// strand shader (strands.frag, per fragment) and the compute rasterizer (raster_shade.comp, per vertex).
// Per light of the frame: S(L, V, T) cos(theta_i) x light x transmittance [+ the light the hair in front
// scattered forward and the light the hair around scatters back, dual scattering]; then sky albedo x (the
// environment's light around the fibre x the sky's visibility (RENDER_HAIR_SKY_VISIBILITY, or with dual
// scattering MarschnerParams.skyVisibility) + the skin's bounce of the slot-0 light, which the caller passes
// in: strand_bounce.comp gathers it along the strands once a frame, bounce_samples.glsl interpolates it), all
// times the strand's lightness variation. The transmittance is the hair's (opacity maps of the light's shadow
// slot) times the heads' (their depth map); a light without a slot is unshadowed.
// The includer declares `frame` (RenderFrame), `marschner` (MarschnerParams), the LUT samplers lutM, lutN0,
// lutN1, and what frame_shadows.glsl needs, before including this file.
#ifndef HP_HAIR_SHADING_GLSL
#define HP_HAIR_SHADING_GLSL
#include "frame_shadows.glsl"
#include "environment.glsl"

// The fibre this pipeline shades (shared/marschner.h HAIR_FIBRE_*): read at run time by default, or fixed.
layout(constant_id = 1) const uint HAIR_FIBRE = HAIR_FIBRE_RUNTIME;

// The fibre model, MARSCHNER_MODE_*.
uint hairFibreMode() { return HAIR_FIBRE == HAIR_FIBRE_RUNTIME ? marschner.control.x : HAIR_FIBRE & HAIR_FIBRE_MODE_MASK; }

// Dual scattering: the physical fibre model's multiple scattering is on.
bool hairDualScattering() {
  if (HAIR_FIBRE != HAIR_FIBRE_RUNTIME) return (HAIR_FIBRE & HAIR_FIBRE_DUAL) != 0u;
  return frame.options.z == RENDER_SCATTERING_DUAL && marschner.control.x == MARSCHNER_MODE_LUT_PHYSICAL;
}

// One light's direct term at a fibre point; `shadow` is what stands between them; tilt and roughness: the
// strand's cuticle tilt offset and beta_R scale (shared/strands.h strandTilt, strandRoughness).
vec3 hairLightRadiance(FrameLight light, LightSample ls, LightShadow shadow, vec3 V, vec3 T, float tilt,
                       float roughness) {
  vec3 L = ls.L;
  bool dual = hairDualScattering();
  // With dual scattering the single and multiple scattering share the angles and the longitudinal terms' lookups.
  vec4 ang = dual ? marschnerAngles(L, V, T) : vec4(0.0);
  vec4 m = dual ? marschnerPhysicalM(ang, tilt, roughness, lutM) : vec4(0.0);
  vec3 S = dual ? marschnerPhysicalS(ang, m, lutN0, lutN1)
                : marschnerEvaluate(hairFibreMode(), L, V, T, lutM, lutN0, lutN1, marschner, tilt,
                                    roughness);
  float sinThetaI = clamp(dot(L, T), -1.0, 1.0);
  float cosThetaI = sqrt(1.0 - sinThetaI * sinThetaI);
  float tau = frame.strand.z * shadow.alpha;  // optical depth toward the light: the mean number of fibres crossed
  vec3 incident = light.radiance.rgb * (ls.scale * shadow.head);
  vec3 direct = S * cosThetaI * incident * exp(-tau);
  // Multiple scattering (dual; docs/SHADING.md "Multiple scattering"): of the light that hits N fibres on
  // its way (N Poisson with mean tau), a fraction d_f a_f^N goes on forward, spread around the fibre:
  // E[a_f^N; N >= 1] = exp(-tau (1 - a_f)) - exp(-tau). The hair around the fibre scatters back A_b of
  // both the unscattered light and that spread light (local back-scattering).
  if (dual) {
    vec3 af = marschnerForwardAlbedo(sinThetaI);
    vec3 spread = MARSCHNER_FORWARD_DENSITY * max(exp(-tau * (1.0 - af)) - exp(-tau), vec3(0.0));
    direct += marschnerPhysicalMultipleResponse(ang, m, exp(-tau), spread) * incident;
  }
  return direct;
}

// 1: every light of the frame, in a loop; 0: the first light only, without one. lavapipe runs this shader
// at half speed with the loop in it, even for one light, so the compute raster's shade pass has a variant
// of each and takes the one-light variant for frames of one light (docs/PERFORMANCE.md "Several lights").
// The graphics strand pass keeps the default.
layout(constant_id = 0) const uint HAIR_LIGHT_LOOP = 1u;

// Light i's direct term.
vec3 hairLight(uint i, vec3 world, vec3 V, vec3 T, float tilt, float roughness) {
  FrameLight light = frame.lights[i];
  LightSample ls = sampleLight(light, world);
  return hairLightRadiance(light, ls, frameLightShadow(light, world, ls.L, false, 0.0), V, T, tilt, roughness);
}

// bounce: the mean radiance the skin sends to this point (head_bounce.glsl; 0 without the skin's bounce);
// colorScale, tilt, roughness: the strand's lightness scale, cuticle tilt offset and beta_R scale (shared/strands.h); headBehind: the
// share of the point's pixel where the head lies behind it along the view ray (the compute raster's shade pass
// reads it from the head's depth; 0 where unknown).
vec3 hairRadiance(vec3 world, vec3 tangent, float colorScale, float tilt, float roughness, float headBehind,
                  vec3 bounce) {
  vec3 T = normalize(tangent);
  vec3 V = normalize(frame.cameraPosition.xyz - world);
  vec3 direct = vec3(0.0);
  if (HAIR_LIGHT_LOOP != 0u) {
    for (uint i = 0u; i < frame.lightCount.x; ++i) direct += hairLight(i, world, V, T, tilt, roughness);
  } else if (frame.lightCount.x > 0u) {
    direct = hairLight(0u, world, V, T, tilt, roughness);
  }
  // The environment (docs/SHADING.md "Environment"): an unoccluded fibre under a uniform sky returns the
  // model's sky albedo times its radiance, a fibre of a head of hair the mean fraction of it that reaches
  // it (shared/render.h); with dual scattering more of it does, passed on forward by the hair on the way
  // (hp::skyVisibility). Under an environment, the albedo's part from the viewer's side of the fibre takes
  // the environment's mean radiance around the fibre's normal toward the viewer, the rest the mean around
  // the opposite normal. With dual scattering, where the head lies behind the fibre, its far side faces the hair
  // beneath and the head instead of the sky: that side gets what the hair beneath passes on forward, a_f of the
  // sky (single scattering keeps it open: its sky term stands for all the light it does not model). The skin's
  // bounce: the fibre's response to it is the sky albedo times its mean.
  bool dual = hairDualScattering();
  vec3 sky = dual ? marschner.skyVisibility.rgb : vec3(RENDER_HAIR_SKY_VISIBILITY);
  vec3 across = V - dot(V, T) * T;
  vec3 side = normalize(cross(T, abs(T.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 N = dot(across, across) > 1e-8 ? normalize(across) : side;  // seen end-on: any side will do
  vec3 front = marschner.skyAlbedoFront.rgb;
  vec3 farShare = dual ? mix(vec3(1.0), marschner.forwardMean.rgb, headBehind) : vec3(1.0);
  vec3 viewerSide, farSide;
  environmentLightBothSides(N, viewerSide, farSide);
  vec3 environment = front * viewerSide + (marschner.skyAlbedo.rgb - front) * farSide * farShare;
  vec3 ambient = environment * sky + marschner.skyAlbedo.rgb * bounce;
  return (direct + ambient) * colorScale;
}
#endif
