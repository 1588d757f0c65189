#pragma once
// Contract: the small frame several render tests draw: the default head with a given number of render
// strands, seen from the front at 160x96 (the head fills most of the height), and a compute raster's settings.
#include "compute/renderer/renderer_settings.h"
#include "engine/core/hair/default_head.h"

namespace hp::test {
inline constexpr std::uint32_t kSmallWidth = 160, kSmallHeight = 96;

inline HairAsset defaultHeadWithStrands(std::uint32_t strands) {
  DensityOptions density;
  density.totalStrands = strands;
  return buildDefaultHeadAsset(defaultHeadGrowth(), density);
}

// A compute-raster Renderer's settings for an application's attachments, with small opacity maps.
inline RendererSettings computeRendererSettings(const hairpipe::AttachmentFormats& formats,
                                                std::uint32_t opacityResolution = 128) {
  RendererSettings s;
  s.formats = formats;
  s.raster = RasterMode::Compute;
  s.opacity.resolution = opacityResolution;
  return s;
}

// From the front, `distance` from a target just below the head's origin.
inline View smallFrontView(float distance = 0.8f) {
  CameraSpec cam;
  cam.orbitDeg = 0.0f;
  cam.elevationDeg = 0.0f;
  cam.distance = distance;
  cam.target = {0.0f, -0.05f, 0.0f};
  return View{orbitCamera(cam, float(kSmallWidth) / kSmallHeight), {kSmallWidth, kSmallHeight}, false, 0};
}
}  // namespace hp::test
