// The light the skin reflects onto a fibre (one bounce, sun -> skin -> fibre; docs/SHADING.md "Skin bounce"),
// GLSL only, gathered at a few points along every strand by strand_bounce.comp (entry point headBounceAt);
// both rasters' hair shading interpolates between those points (bounce_samples.glsl). The light is the frame's light in shadow slot 0 (RenderFrame::lightCount.y);
// the others add no skin bounce. The includer declares what frame_shadows.glsl needs and the bounce map's
// samplers bounceFlux and bouncePosition (head_bounce.frag writes them).
// Each texel of the map is a Lambertian patch of flux Phi; a point p receives from it the radiance
// integral L A cos / r^2 = Phi cos_out / (pi r^2) (cos_out at the patch toward p), times the hair between
// them, hairTransmittance(k (alpha_skin - alpha_p)): both opacity-map values are along the light, so their difference is
// the hair between the two depths. The patches are gathered on rings around p's texel (shared/render.h),
// each sample standing for its ring's share of texels. p is lifted one texel off each patch's plane so a
// fibre lying on the skin sees it as the hemisphere it is, not as grazing patches.
// Returns the mean incident radiance over the sphere, (1/4pi) int L dw, which the fibre turns into
// outgoing radiance with its sky albedo (hair_shading.glsl).
#ifndef HP_HEAD_BOUNCE_GLSL
#define HP_HEAD_BOUNCE_GLSL
#include "head_bounce_encoding.glsl"
#include "frame_shadows.glsl"

// p's texel of the bounce map (continuous, in texels); false behind a spot.
bool headBounceTexel(vec3 p, out vec2 centre) {
  vec4 clip = frame.shadows[0].headViewProj * vec4(p, 1.0);
  if (!(clip.w > 0.0)) return false;
  vec2 ndc = clip.xy / clip.w;
  centre = vec2(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5) * float(RENDER_BOUNCE_RESOLUTION);  // head_shadow.glsl's y flip
  return true;
}

// Where the caller looks up the hair below p: p moved along the light (L toward it) to the depth of the skin
// in p's texel, or far behind everything where the texel holds no skin (the whole column behind p then
// stands between: a bound rather than a guess).
vec3 headBounceSkinBelow(vec3 p, vec3 L) {
  vec2 centre;
  if (headBounceTexel(p, centre)) {
    ivec2 t = ivec2(floor(centre));
    if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, ivec2(RENDER_BOUNCE_RESOLUTION))) &&
        texelFetch(bounceFlux, t, 0).a >= 0.5)
      return p - L * max(dot(p - texelFetch(bouncePosition, t, 0).xyz, L), 0.0);
  }
  return p - L * (2.0 * frame.headBounce.y * float(RENDER_BOUNCE_RESOLUTION));  // two map widths behind
}

// alphaLayer: the hair between p and the skin below it along the light (the caller's lookup at
// headBounceSkinBelow minus alphaHere), which every patch's light crosses to reach a fibre on top of it.
vec3 headBounceLight(vec3 p, float alphaHere, float alphaLayer) {
  vec2 centre;
  if (frame.headBounce.x == 0.0 || !headBounceTexel(p, centre)) return vec3(0.0);
  float lift = max(frame.headBounce.y, 1e-6);  // > 0: no division by zero for a patch at p
  const float PI = 3.14159265;
  const float rings = float(RENDER_BOUNCE_RINGS), spokes = float(RENDER_BOUNCE_SPOKES);
  vec3 sum = vec3(0.0);
  for (uint j = 0u; j < RENDER_BOUNCE_RINGS; ++j) {
    float fj = float(j);
    float radius = RENDER_BOUNCE_RADIUS * (fj + 0.5) * (fj + 0.5) / (rings * rings);
    // The ring's annulus, between the radii at j and j + 1, in texels, shared by its spokes.
    float outer = (fj + 1.0) / rings, inner = fj / rings;
    float texels = PI * RENDER_BOUNCE_RADIUS * RENDER_BOUNCE_RADIUS *
                   (outer * outer * outer * outer - inner * inner * inner * inner) / spokes;
    for (uint k = 0u; k < RENDER_BOUNCE_SPOKES; ++k) {
      float angle = 2.0 * PI * (float(k) + 0.61803399 * fj) / spokes;
      ivec2 t = ivec2(floor(centre + radius * vec2(cos(angle), sin(angle))));
      if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(RENDER_BOUNCE_RESOLUTION)))) continue;
      vec4 flux = texelFetch(bounceFlux, t, 0);
      if (flux.a < 0.5) continue;  // no skin there
      vec4 skin = texelFetch(bouncePosition, t, 0);
      vec3 n = bounceDecodeNormal(skin.w);
      vec3 d = p - skin.xyz;
      float h = dot(n, d);
      if (h < -lift) continue;  // behind the patch's plane
      float lifted = max(h, 0.0) + lift;
      float r2 = dot(d, d) - h * h + lifted * lifted;
      vec3 between = hairTransmittance(frame.strand.z * max(max(flux.a - 1.0 - alphaHere, 0.0), alphaLayer));
      sum += flux.rgb * (texels * lifted * inversesqrt(r2) / (PI * r2) * between);
    }
  }
  return sum / (4.0 * PI);
}

// The mean radiance the skin sends to hair point p (L toward the bounce's light; alphaHere: the opacity-map
// value of slot 0 at p), or 0 when the frame has no bounce.
vec3 headBounceAt(vec3 p, vec3 L, float alphaHere) {
  if (frame.headBounce.x == 0.0) return vec3(0.0);
  float layer = frameOpacityAlpha(0u, headBounceSkinBelow(p, L), false) - alphaHere;
  return headBounceLight(p, alphaHere, max(layer, 0.0));
}
#endif
