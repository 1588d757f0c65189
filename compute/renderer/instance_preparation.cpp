#include "compute/renderer/instance_preparation.h"

#include "compute/head/skin_transfer_buffer.h"
#include "engine/core/shading/lut_cache.h"

namespace hp {
void prepareInstance(const HairAsset& asset, const InstanceSettings& settings) {
  settings.validate();
  sharedMarschnerParams(settings.lutMode, settings.material);  // and its tables: what Renderer::marschner takes
  if (settings.drawHead) render::prepareSkinTransfer(asset.head);
}
}  // namespace hp
