#pragma once
// CPU references for the opacity shadow maps (docs/THEORY.md §5), in double precision:
//  - lightBounds: the light-space box of a set of points (what the bounds pass reduces);
//  - rasterizeSegments/Triangles: alpha(z_i) of line segments (texel centres inside the 1-texel-wide
//    rectangle along the segment: Vulkan's strict-line rule, which lavapipe uses) and of triangles
//    (texel centres inside), each fragment adding its opacity to every slice at or behind it;
//  - lookupAlpha: eq. 10 with w_i = max(0, 1 - |s - i|) on a captured map at one texel.
// Framing (the viewProj) is taken from the device's LightSpace, so the references test the
// rasterization and slicing, and lightBounds tests the framing.
#include <glm/glm.hpp>

#include <array>
#include <vector>

#include "samples/tools/opacity_capture.h"

namespace hp::test {
struct LightBox {
  glm::dvec3 lo{1e300}, hi{-1e300};  // light x, y, depth d = -L.p
};
LightBox lightBounds(const std::vector<glm::vec4>& points, const glm::vec3& towardLight);
// Spot: the box of (x/d, y/d, d) measured from `position` over the points with d > kSpotNearLimit.
LightBox spotBounds(const std::vector<glm::vec4>& points, const glm::vec3& position, const glm::vec3& towardLight);

struct OpacityGrid {
  std::uint32_t resolution = 0;
  std::vector<double> alpha;  // slice-major, rows top to bottom, like OpacityCapture
  double at(std::uint32_t slice, std::uint32_t x, std::uint32_t y) const {
    return alpha[(std::size_t(slice) * resolution + y) * resolution + x];
  }
};

// Texel coordinates (x right, y down, texel centres at +0.5) and slice coordinate s of a world point
// (uv from clip.xy / clip.w, s = 16 clip.z: both light types, shared/opacity.h).
glm::dvec3 texelAndSlice(const gpu::LightSpace& light, std::uint32_t resolution, const glm::dvec3& world);

// Adds segments a-b (world space) with `opacity` each.
void rasterizeSegments(OpacityGrid& grid, const gpu::LightSpace& light, const std::vector<glm::dvec3>& a,
                       const std::vector<glm::dvec3>& b, double opacity);
void rasterizeTriangles(OpacityGrid& grid, const gpu::LightSpace& light, const std::vector<glm::dvec3>& corners,
                        double opacity);

double lookupAlpha(const render::OpacityCapture& capture, std::uint32_t x, std::uint32_t y, double s);
}  // namespace hp::test
