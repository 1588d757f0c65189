#include "compute/renderer/raster_target.h"

#include "engine/core/error.h"

namespace hp {
const ComputeRaster& RasterTarget::raster() const {
  if (!raster_) throw Error("Renderer: the raster target has no instance to draw (its instances were destroyed, or a rebuild "
                "failed): " + emptyHint_);
  return *raster_;
}
}  // namespace hp
