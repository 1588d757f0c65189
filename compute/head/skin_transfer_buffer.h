#pragma once
// Contract: a head mesh's skin transfer (engine/core/hair/skin_transfer.h) computed and uploaded once, in
// head.vert's layout (shaders/shared/render.h RENDER_BINDING_SKIN_TRANSFER: SKIN_TRANSFER_FLOATS floats per
// vertex). Immutable after construction, so instances drawing the same mesh share one (Renderer caches it by
// the mesh's contents); the computed values of the last 4 meshes are also kept for the process, so another
// Renderer drawing the same mesh uploads them without casting the rays again. `fingerprint` is both caches' key.
#include <cstdint>

#include "engine/core/hair/hair_asset.h"
#include "engine/vk/buffer.h"

namespace hp::render {
class SkinTransferBuffer {
 public:
  // The mesh non-empty; key: fingerprint(mesh), which the caller's own cache has already computed.
  SkinTransferBuffer(const vk::Context& ctx, const HeadMesh& mesh, std::uint64_t key);
  const vk::Buffer& buffer() const { return buffer_; }
  std::uint32_t vertexCount() const { return vertexCount_; }

 private:
  std::uint32_t vertexCount_ = 0;
  vk::Buffer buffer_;
};

// A 64-bit hash of everything the transfer depends on: positions, normals, indices and scalp weights.
std::uint64_t fingerprint(const HeadMesh& mesh);
// The mesh's transfer computed into the process's values now, on the calling thread (any thread; nothing for
// an empty mesh), so a later SkinTransferBuffer of it only uploads.
void prepareSkinTransfer(const HeadMesh& mesh);
// Transfers the process has computed (values taken from its cache not counted).
std::uint64_t skinTransfersComputed();
}  // namespace hp::render
