#include "engine/core/hair/mesh_simplify_cache.h"

#include <optional>
#include <vector>

#include "engine/core/byte_stream.h"
#include "engine/core/error.h"
#include "engine/core/hair/head_mesh_bytes.h"

namespace hp {
namespace {
// Every field of the options is in the key; one added there must be added here too.
static_assert(sizeof(SimplifyOptions) == 2 * sizeof(float) + sizeof(std::uint32_t));

// The mesh an entry holds, if it decodes whole into a well-formed one.
std::optional<HeadMesh> decoded(std::span<const std::byte> bytes) {
  try {
    ByteReader in(bytes, "simplified mesh entry");
    HeadMesh mesh = readHeadMesh(in);
    if (in.atEnd()) return mesh;
  } catch (const Error&) {
  }
  return std::nullopt;
}
}  // namespace

// The whole source mesh (a 64-bit fingerprint could collide) and the options.
std::vector<std::byte> simplifiedMeshKey(const HeadMesh& mesh, const SimplifyOptions& options) {
  ByteWriter key;
  writeHeadMesh(key, mesh);
  key.put(options.maxError);
  key.put(options.maxNormalDegrees);
  key.put(options.targetTriangles);
  return key.take();
}

HeadMesh simplifyMeshCached(const DiskCache& disk, const HeadMesh& mesh, const SimplifyOptions& options) {
  if (!disk.enabled()) return simplifyMesh(mesh, options);
  const std::vector<std::byte> key = simplifiedMeshKey(mesh, options);
  if (const std::optional<std::vector<std::byte>> value = disk.load(kSimplifiedMeshKind, key))
    if (std::optional<HeadMesh> kept = decoded(*value)) return std::move(*kept);
  HeadMesh simplified = simplifyMesh(mesh, options);
  ByteWriter value;
  writeHeadMesh(value, simplified);
  disk.store(kSimplifiedMeshKind, key, value.bytes());
  return simplified;
}
}  // namespace hp
