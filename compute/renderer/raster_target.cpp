#include "compute/renderer/raster_target.h"

#include <algorithm>

#include "engine/core/error.h"

namespace hp {
const ComputeRaster& RasterTarget::raster() const {
  if (!raster_)
    throw Error("Renderer: the raster target has no instance to draw (its instances were destroyed, or a rebuild "
                "failed" + (failure_.empty() ? std::string() : ": " + failure_) + "): " + emptyHint_);
  return *raster_;
}

bool RasterTarget::holds(const HairInstance* instance) const {
  if (rebuild_) return std::find(rebuild_->begin(), rebuild_->end(), instance) != rebuild_->end();
  return raster_ && raster_->holds(instance);
}
}  // namespace hp
