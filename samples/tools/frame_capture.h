#pragma once
// Contract: what `renderStill` reads back of the drawn frame when asked (RenderRequest::captureFrame),
// for frame exports and the path-traced reference: the render strands exactly as drawn (positions with
// the along-strand parameter in w, tangents, per-strand width/colour scales), the head's placement,
// the camera, the linear HDR image before exposure and tonemap, and, with the compute raster, the
// hair's coverage (1 - transmittance) per pixel.
#include <glm/glm.hpp>

#include "compute/strands/strand_buffers.h"
#include "compute/raster/camera.h"
#include "samples/tools/linear_image.h"

namespace hp {
struct FrameCapture {
  compute::StrandData strands;
  std::uint32_t verticesPerStrand = 0;
  glm::mat4 headToWorld{1.0f};
  CameraMatrices camera;
  LinearImage linear;     // RGB, radiance in the light's units, before exposure
  LinearImage hairAlpha;  // 1 channel; empty (0 x 0) with the graphics raster
  LinearImage motion;     // 3 channels: the hair's screen motion x, y in pixels and 0; empty without motion vectors
};
}  // namespace hp
