// A frame's shadows per light, GLSL only, for the shading passes: the hair's opacity maps and the heads'
// depth map of the light's shadow slot (shared/opacity.h), looked up per shaded point. The includer
// declares `frame` (RenderFrame), `lightSpaces` (the LightSpace of each slot), `opacityMaps` and
// `headShadowMap` after including shared/render.h.
#ifndef HP_FRAME_SHADOWS_GLSL
#define HP_FRAME_SHADOWS_GLSL
#include "shared/opacity.h"
#include "head_shadow.glsl"
#include "light.glsl"

// What light crossing optical depth tau of hair on its way to or from the skin keeps: the unscattered part,
// and with dual scattering (frame.hairForward, 0 otherwise) also d_f of what the hair on the way passes on
// forward, E[a_f^N; N >= 1] = exp(-tau (1 - a_f)) - exp(-tau) (the skin is Lambertian: the spread in
// direction does not matter to it; docs/SHADING.md "Skin bounce").
vec3 hairTransmittance(float tau) { return hairpipeHairTransmittance(tau, frame.hairForward); }

// The opacity-map value at p for shadow slot `slot`, with the frame's kind of slices and bias. `soft`: over
// a few texels (opaque receivers: hairpipeShadowAlphaSoft). The lookups are the ones applications call
// (public/hairpipe/hair_shadows.glsl, included by shared/opacity.h).
float frameOpacityAlpha(uint slot, vec3 p, bool soft) {
  if (frame.options.y == 0u) return 0.0;  // the hair casts no shadow
  HairpipeShadowPoint o = hairpipeShadowPoint(lightSpaces[slot].viewProj, p);
  bool deep = frame.options.w != 0u;
  return soft ? hairpipeShadowAlphaSoft(opacityMaps, slot, o.uvw, o.s, deep, frame.strand.w)
              : hairpipeShadowAlpha(opacityMaps, slot, o.uvw, o.s, deep, frame.strand.w);
}

// What stands between p and a light: alpha, the hair's opacity-map value (0 for an unshadowed light), and
// head, the fraction of the light the heads let through (1 for an unshadowed light).
struct LightShadow {
  float alpha;
  float head;
};

// slopeTan: headVisibility's, 0 for hair.
LightShadow frameLightShadow(FrameLight light, vec3 p, vec3 L, bool soft, float slopeTan) {
  LightShadow s = LightShadow(0.0, 1.0);
  int slot = lightSlot(light);
  if (slot < 0) return s;
  s.alpha = frameOpacityAlpha(uint(slot), p, soft);
  s.head = headVisibility(headShadowMap, uint(slot), frame.shadows[slot], p, L, slopeTan);
  return s;
}
#endif
