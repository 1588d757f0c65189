#pragma once
// Contract: a head mesh's skin transfer (skin_transfer.h, default options) packed as head.vert reads it
// (shaders/shared/render.h: SKIN_TRANSFER_FLOATS floats per vertex: the occluded SH, the bounce SH, the reflecting
// share), read from a disk cache (engine/core/disk_cache.h) when it holds this mesh's, else computed and kept there.
// The cache's key is the whole mesh, so a hit is this mesh's transfer, bit for bit what computing it gives.
#include <vector>

#include "engine/core/disk_cache.h"
#include "engine/core/hair/hair_asset.h"

namespace hp {
std::vector<float> packSkinTransfer(const HeadMesh& mesh);  // computed, no cache
std::vector<float> packedSkinTransfer(const HeadMesh& mesh, const DiskCache& disk = DiskCache::process());
}  // namespace hp
