// The light at a shaded point, GLSL only, for strands.frag and head.frag (RenderFrame in shared/render.h).
// Directional: L = lightDirection everywhere, full radiance. Spot: L = normalize(position - p), and
// the radiance is scaled by
//   cone:     smoothstep(cos(cone), cos(inner), dot(L, -axis)): 1 inside the inner angle (80% of the
//             half-angle), fading to 0 at the cone's edge, 0 outside (no direct light);
//   distance: (range / max(distance, range / 10))^2 when range > 0 (inverse square, 1 at `range`,
//             clamped near the spot), 1 when range = 0.
#ifndef HP_LIGHT_GLSL
#define HP_LIGHT_GLSL

struct LightSample {
  vec3 L;       // unit, from p toward the light
  float scale;  // fraction of lightRadiance reaching p (before shadowing)
};

LightSample sampleLight(vec4 direction, vec4 position, vec4 spot, vec3 p) {
  LightSample s;
  s.L = direction.xyz;
  s.scale = 1.0;
  if (position.w == 0.0) return s;
  vec3 toLight = position.xyz - p;
  float dist = length(toLight);
  s.L = toLight / max(dist, 1e-6);
  s.scale = smoothstep(spot.x, spot.y, dot(s.L, direction.xyz));  // direction = -axis: both toward the light
  if (spot.z > 0.0) {
    float r = spot.z / max(dist, 0.1 * spot.z);
    s.scale *= r * r;
  }
  return s;
}
#endif
