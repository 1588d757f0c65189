#pragma once
// Contract: simplifyMesh through a DiskCache (kind "simplified-mesh"): the entry is keyed by the options and the
// whole source mesh (its every position, normal, index and scalp weight), so a process of the same build
// that simplifies the same mesh (the default head, in every process that draws it: ~0.2 s of one thread) reads
// the result instead. A disabled cache, a miss, or an entry that does not decode into a well-formed mesh (normals
// and scalp weights per position, whole triangles, indices in range) simplifies; the result is then stored.
// Returns exactly what simplifyMesh returns.
#include <cstddef>
#include <vector>

#include "engine/core/disk_cache.h"
#include "engine/core/hair/mesh_simplify.h"

namespace hp {
HeadMesh simplifyMeshCached(const DiskCache& disk, const HeadMesh& mesh, const SimplifyOptions& options);
// The entry's kind and key (tests plant entries under them).
inline constexpr const char* kSimplifiedMeshKind = "simplified-mesh";
std::vector<std::byte> simplifiedMeshKey(const HeadMesh& mesh, const SimplifyOptions& options);
}  // namespace hp
