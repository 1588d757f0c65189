#include "engine/error.h"
#include "engine/hair/scene.h"

namespace hp {
RasterMode parseRasterMode(const std::string& text) {
  if (text == "auto") return RasterMode::Auto;
  if (text == "compute") return RasterMode::Compute;
  if (text == "graphics") return RasterMode::Graphics;
  throw Error("raster must be auto, compute or graphics, got '" + text + "'");
}

const char* rasterModeName(RasterMode mode) {
  switch (mode) {
    case RasterMode::Auto: return "auto";
    case RasterMode::Compute: return "compute";
    case RasterMode::Graphics: return "graphics";
  }
  return "auto";
}
}  // namespace hp
