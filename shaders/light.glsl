// The light at a shaded point, GLSL only, for the shading passes (FrameLight in shared/render.h).
// Directional: L = direction everywhere, full radiance. Spot and point: L = normalize(position - p), and
// the radiance is scaled by
//   cone (spot): smoothstep(cos(cone), cos(inner), dot(L, -axis)): 1 inside the inner angle (80% of the
//                half-angle), fading to 0 at the cone's edge, 0 outside (no direct light);
//   distance:    (range / max(distance, range / 10))^2 when range > 0 (inverse square, 1 at `range`,
//                clamped near the light), 1 when range = 0.
#ifndef HP_LIGHT_GLSL
#define HP_LIGHT_GLSL

struct LightSample {
  vec3 L;       // unit, from p toward the light
  float scale;  // fraction of the light's radiance reaching p (before shadowing)
};

LightSample sampleLight(FrameLight light, vec3 p) {
  LightSample s;
  s.L = light.direction.xyz;
  s.scale = 1.0;
  if (light.position.w == RENDER_LIGHT_DIRECTIONAL) return s;
  vec3 toLight = light.position.xyz - p;
  float dist = length(toLight);
  s.L = toLight / max(dist, 1e-6);
  if (light.position.w == RENDER_LIGHT_SPOT)  // direction = -axis: both toward the light
    s.scale = smoothstep(light.spot.x, light.spot.y, dot(s.L, light.direction.xyz));
  if (light.spot.z > 0.0) {
    float r = light.spot.z / max(dist, 0.1 * light.spot.z);
    s.scale *= r * r;
  }
  return s;
}

// The light's shadow slot (shared/opacity.h), or -1 when it casts no hair shadow.
int lightSlot(FrameLight light) { return int(light.direction.w); }
#endif
