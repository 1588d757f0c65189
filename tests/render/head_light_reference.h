#pragma once
// CPU reference of where the default head's own shadows fall, independent of the renderer's shadow
// maps: per pixel of an orbit camera, a sphere trace of the head's distance grid (the field the head
// mesh is meshed from), then a shadow ray toward a directional light through the same grid. A pixel is
// "clear lit" when the head is seen there, the light reaches it, the shadow ray passes at least
// `margin` from the surface (so no cast-shadow edge is near: the grid, the mesh and any shadow map
// may place the edge up to that far apart) and N.L >= minCosine (away from the terminator, where
// shading and self-shadow meet). Banding tests measure only there: any luminance step the shadows
// add in clear-lit pixels is an artefact, not a true shadow.
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "engine/core/hair/scene.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp::test {
struct HeadLightOptions {
  float margin = 0.01f;     // scene units (m)
  float minCosine = 0.2f;   // N.L
  // For a point facing away from the light (N.L < 0, the wrap-lit side): its shadow ray starts where it
  // leaves the head's own body, so "clear" means no other part of the head stands between it and the light.
  // (The renderer's depth map of back faces does not let a body shadow its own far side.)
  bool pastOwnBody = false;
};

struct HeadLightMap {
  std::uint32_t width = 0, height = 0;
  std::vector<bool> hit;        // the head is seen at the pixel centre
  std::vector<bool> clearLit;   // see the contract above
};

HeadLightMap traceHeadLight(const SdfGrid& head, const CameraSpec& camera, const LightSpec& light,
                            std::uint32_t width, std::uint32_t height, const HeadLightOptions& options = {});
}  // namespace hp::test
