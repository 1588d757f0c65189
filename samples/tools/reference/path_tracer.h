#pragma once
// Contract: the ground-truth reference of an exported frame, path traced on the CPU
// (`hairpipe reference`, docs/SHADING.md "Reference"). Per pixel, `spp` camera rays over the pixel's
// square, stratified when spp is a square number (the box filter the real-time coverage integrates). At every scattering
// vertex (up to `bounces`): every light by next-event estimation with a shadow ray each (they are delta
// lights: no other way reaches them), and one continuation direction: at a fibre importance-sampled from
// its lobes (physical_sampling.h for the physical model, fibre_sampling.h for the paper's; weight
// S cos(theta_i) / pdf times the strand's lightness scale, S of the strand's own material: its cuticle tilt
// offset added, ExportedFrame::strandMaterial; the
// far-field fibre scatters over its width: shadow and continuation rays leave from the side of its tube
// that faces them, reference_scene.h), cosine-weighted at the Lambertian
// head (weight albedo). A continuation ray that escapes brings the uniform white environment (the
// real-time ambient strength) and, when the frame has an environment map, the map's radiance in its
// direction; the map is also sampled by next-event estimation at every vertex (environment_sampler.h, a
// shadow ray each), the two weighted by the power heuristic. A camera ray that escapes sees the background. Russian roulette after
// 3 vertices. The result is deterministic for a seed whatever the thread count: each pixel's samples
// depend only on (seed, pixel, sample). Progress lines on `progress` (tiles done, rate, ETA) at most
// once a second when given.
#include <cstdint>
#include <functional>
#include <iosfwd>

#include "samples/tools/frame_export.h"
#include "samples/tools/linear_image.h"

namespace hp::reference {
struct TraceSettings {
  std::uint32_t spp = 64;
  std::uint32_t bounces = 8;     // scattering vertices per path, >= 1
  std::uint64_t seed = 1;
  std::uint32_t threads = 0;     // 0: every hardware thread
  std::ostream* progress = nullptr;
  // Polled every 1024 samples of a pixel: true stops the trace (traceReference then throws hp::Error).
  // None: run on.
  std::function<bool()> stop;
  void validate() const;         // throws hp::Error naming the setting
};

struct TraceResult {
  LinearImage radiance;       // RGB linear radiance (before exposure), rows top to bottom
  LinearImage hairCoverage;   // fraction of camera rays whose first hit is a fibre
  double seconds = 0.0;
  std::uint64_t paths = 0;
  std::uint32_t threads = 0;
};

TraceResult traceReference(const ExportedFrame& frame, const TraceSettings& settings);
}  // namespace hp::reference
