#pragma once
// Contract: a compute raster target as its holders see it (the Renderer's own, which setRasterTarget sets,
// and each one createRasterTarget makes for an application): the ComputeRaster of one extent, depth view and
// set of instances. The Renderer swaps that raster in place (the old one retired after its frames) when an
// instance in it changes strands or goes (in the frame loop at the next frame's first record call), so a
// holder's handle stays valid across the change; the target is
// empty once none of its instances is left or a rebuild failed, and raster() then says it cannot draw.
// Holders share one through a shared_ptr and give it back with Renderer::destroyRasterTarget, which retires
// its raster for the frames in flight: the last reference dropped without that destroys the raster at once.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compute/renderer/compute_raster.h"

namespace hp {
class RasterTarget {
 public:
  // `emptyHint`: what raster() tells a caller of an empty target to do (set or create it again).
  RasterTarget(std::shared_ptr<ComputeRaster> raster, std::string emptyHint)
      : raster_(std::move(raster)), emptyHint_(std::move(emptyHint)) {}
  RasterTarget(const RasterTarget&) = delete;  // one object the Renderer rebuilds: a copy would not be
  RasterTarget& operator=(const RasterTarget&) = delete;

  // Throws hp::Error with the hint (and why a rebuild failed) while the target is empty.
  const ComputeRaster& raster() const;
  ComputeRaster& raster() { return const_cast<ComputeRaster&>(std::as_const(*this).raster()); }
  // Whether the instance is one the target draws from the next frame on (a waiting rebuild's, else its raster's).
  bool holds(const HairInstance* instance) const;

 private:
  friend class Renderer;
  std::shared_ptr<ComputeRaster> raster_;  // null: empty
  // In the frame loop, an instance's change (destroyed, new strands) rebuilds the target at the next frame's
  // first record call: these are its instances then. Until then raster_ draws what this frame's shadows hold.
  std::optional<std::vector<HairInstance*>> rebuild_;
  std::string emptyHint_;
  std::string failure_;  // why the last rebuild failed (empty: none did)
};
}  // namespace hp
