#include "compute/head/skin_transfer_buffer.h"

#include <memory>
#include <span>

#include "engine/core/error.h"
#include "engine/core/fnv1a.h"
#include "engine/core/hair/skin_transfer_cache.h"
#include "engine/core/recent_cache.h"
#include "engine/vk/transfer.h"

namespace hp::render {
namespace {
// The last few meshes' packed transfers, shared by every Renderer of the process: the transfer is a pure
// function of the mesh, and a process that makes several Renderers (a tool comparing settings, a test, an
// engine recreating its device) would otherwise cast the same rays again. Keyed by the fingerprint and the
// vertex count; 2.5 MiB each for the default head. Never destroyed, like the tables' cache.
using TransferCache = RecentCache<std::pair<std::uint64_t, std::size_t>, std::vector<float>, 4>;

TransferCache& transfers() {
  static auto& cache = *new TransferCache;
  return cache;
}

std::shared_ptr<const std::vector<float>> packed(const HeadMesh& mesh, std::uint64_t key) {
  return transfers().get({key, mesh.positions.size()}, [&] { return packedSkinTransfer(mesh); });
}

// FNV-1a over a span's bytes, then its length (two meshes whose arrays split the same bytes differently differ).
template <typename T>
void hashInto(std::uint64_t& h, const std::vector<T>& values) {
  h = fnv1a(std::as_bytes(std::span(values)), h);
  h = (h ^ values.size()) * kFnvPrime;
}
}  // namespace

SkinTransferBuffer::SkinTransferBuffer(const vk::Context& ctx, const HeadMesh& mesh, std::uint64_t key)
    : vertexCount_(static_cast<std::uint32_t>(mesh.positions.size())) {
  if (mesh.positions.empty()) throw Error("skin transfer: the head mesh is empty");
  const std::shared_ptr<const std::vector<float>> values = packed(mesh, key);
  buffer_ = vk::Buffer(ctx, values->size() * sizeof(float),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       vk::MemoryKind::DeviceLocal, "head skin transfer");
  vk::upload<float>(ctx, buffer_, *values, vk::BufferUse::VertexRead);
}

std::uint64_t fingerprint(const HeadMesh& mesh) {
  std::uint64_t h = kFnvOffsetBasis;
  hashInto(h, mesh.positions);
  hashInto(h, mesh.normals);
  hashInto(h, mesh.indices);
  hashInto(h, mesh.scalp);
  return h;
}
void prepareSkinTransfer(const HeadMesh& mesh) {
  if (!mesh.positions.empty()) packed(mesh, fingerprint(mesh));
}

std::uint64_t skinTransfersComputed() { return transfers().made(); }
}  // namespace hp::render
