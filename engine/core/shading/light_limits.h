#pragma once
// Contract: the brightest a light may be, intensity x its largest colour component, wherever a light comes
// from (a scene's, the API's, one an environment map's bright region becomes): the default light's 3,333
// times, within what the half-float radiance images hold after shading (at most 65504; a brighter light
// turned the lit hair infinite, then black). Physical units (a sun of 100,000 lux) are scaled down by the
// caller, and the exposure up.
namespace hp {
inline constexpr float kMaxLightRadiance = 1.0e4f;
}  // namespace hp
