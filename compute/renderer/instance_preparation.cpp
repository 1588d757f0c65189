#include "compute/renderer/instance_preparation.h"

#include "compute/head/skin_transfer_buffer.h"
#include "engine/core/shading/lut_cache.h"

namespace hp {
void prepareInstance(const HairAsset& asset, const InstanceSettings& settings) {
  settings.validate();
  sharedLut(settings.lutMode, settings.material);  // what Renderer::marschner takes for this material
  if (settings.drawHead) render::prepareSkinTransfer(asset.head);
}
}  // namespace hp
