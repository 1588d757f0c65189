#pragma once
// Contract: the CPU start-up work of an instance (Renderer::createInstance) done ahead, on any thread and
// without a device: the material's lookup tables and their parameter block (sharedLut, sharedMarschnerParams)
// and, where the instance draws its head, the
// head mesh's skin transfer (prepareSkinTransfer), each into the process's cache of the last 4, so a
// createInstance that follows soon on the thread recording frames takes them from there instead of
// computing them (~0.5 s and ~0.25-0.55 s on the 2-core VM for the default head's). Thread-safe (the caches
// lock); throws hp::Error for settings createInstance would refuse.
#include "compute/renderer/renderer_settings.h"
#include "engine/core/hair/hair_asset.h"

namespace hp {
void prepareInstance(const HairAsset& asset, const InstanceSettings& settings);
}  // namespace hp
