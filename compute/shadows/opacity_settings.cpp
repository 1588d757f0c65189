#include "compute/shadows/opacity_settings.h"

#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/error.h"
#include "shaders/shared/opacity.h"

namespace hp::render {
namespace {
void checkRange(float value, float lo, float hi, bool loOpen, const char* field) {
  const bool ok = std::isfinite(value) && (loOpen ? value > lo : value >= lo) && value <= hi;
  if (ok) return;
  std::ostringstream m;
  m << "opacity settings: " << field << " must be in " << (loOpen ? "(" : "[") << lo << ", " << hi << "], got "
    << value;
  throw Error(m.str());
}
}  // namespace

OpacityRaster parseOpacityRaster(const std::string& text) {
  if (text == "auto") return OpacityRaster::Auto;
  if (text == "compute") return OpacityRaster::Compute;
  if (text == "graphics") return OpacityRaster::Graphics;
  throw Error("opacity raster must be auto, compute or graphics, got '" + text.substr(0, 40) + "'");
}

const char* opacityRasterName(OpacityRaster raster) {
  switch (raster) {
    case OpacityRaster::Auto: return "auto";
    case OpacityRaster::Compute: return "compute";
    case OpacityRaster::Graphics: return "graphics";
  }
  return "auto";
}

void validate(const OpacitySettings& s) {
  if (s.resolution < 16 || s.resolution > 4096)
    throw Error("opacity settings: resolution must be in [16, 4096], got " + std::to_string(s.resolution));
  checkRange(s.strandOpacity, 0.0f, 100.0f, true, "strandOpacity");
  checkRange(s.headOpacity, 0.0f, 1.0e4f, false, "headOpacity");
  if (s.headShadowResolution < 16 || s.headShadowResolution > 8192)
    throw Error("opacity settings: headShadowResolution must be in [16, 8192], got " +
                std::to_string(s.headShadowResolution));
  checkRange(s.k, 0.0f, 1.0e3f, false, "k");
  checkRange(s.biasSlices, 0.0f, float(gpu::OPACITY_SLICES), false, "biasSlices");
  checkRange(s.deepBiasSlices, 0.0f, float(gpu::OPACITY_SLICES), false, "deepBiasSlices");
  if (s.format != VK_FORMAT_R32G32B32A32_SFLOAT && s.format != VK_FORMAT_R16G16B16A16_SFLOAT)
    throw Error("opacity settings: format must be RGBA32F or RGBA16F");
  if (s.raster != OpacityRaster::Auto && s.raster != OpacityRaster::Compute && s.raster != OpacityRaster::Graphics)
    throw Error("opacity settings: raster must be Auto, Compute or Graphics");
}
}  // namespace hp::render
