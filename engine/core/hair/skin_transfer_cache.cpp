#include "engine/core/hair/skin_transfer_cache.h"

#include <algorithm>
#include <cstring>
#include <span>

#include "engine/core/byte_stream.h"
#include "engine/core/hair/head_mesh_bytes.h"
#include "engine/core/hair/skin_transfer.h"
#include "shaders/shared/render.h"

namespace hp {
// head.vert reads a vertex's floats as five vec4s in this order.
static_assert(gpu::SKIN_TRANSFER_FLOATS == 20 && gpu::SKIN_TRANSFER_BOUNCE == 9 && gpu::SKIN_TRANSFER_REFLECTING == 18);

namespace {
constexpr const char* kTransferKind = "skin-transfer";

// The whole mesh (a 64-bit fingerprint could collide) and the options the transfer is computed with.
std::vector<std::byte> diskKey(const HeadMesh& mesh) {
  ByteWriter out;
  writeHeadMesh(out, mesh);
  const SkinTransferOptions options;
  out.put(options.raysPerVertex);
  out.put(options.smoothingPasses);
  return out.take();
}
}  // namespace

std::vector<float> packSkinTransfer(const HeadMesh& mesh) {
  const SkinTransfer t = computeSkinTransfer(mesh);
  std::vector<float> out(mesh.positions.size() * gpu::SKIN_TRANSFER_FLOATS, 0.0f);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    float* at = &out[v * gpu::SKIN_TRANSFER_FLOATS];
    std::copy(t.occluded[v].begin(), t.occluded[v].end(), at);
    std::copy(t.bounce[v].begin(), t.bounce[v].end(), at + gpu::SKIN_TRANSFER_BOUNCE);
    at[gpu::SKIN_TRANSFER_REFLECTING] = t.reflecting[v];
  }
  return out;
}

std::vector<float> packedSkinTransfer(const HeadMesh& mesh, const DiskCache& disk) {
  if (!disk.enabled()) return packSkinTransfer(mesh);
  const std::vector<std::byte> key = diskKey(mesh);
  const std::size_t floats = mesh.positions.size() * gpu::SKIN_TRANSFER_FLOATS;
  if (const auto value = disk.load(kTransferKind, key); value && value->size() == floats * sizeof(float)) {
    std::vector<float> packed(floats);
    if (floats > 0) std::memcpy(packed.data(), value->data(), value->size());
    return packed;
  }
  std::vector<float> packed = packSkinTransfer(mesh);
  disk.store(kTransferKind, key, std::as_bytes(std::span(packed)));
  return packed;
}
}  // namespace hp
