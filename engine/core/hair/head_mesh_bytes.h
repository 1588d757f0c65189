#pragma once
// Contract: a HeadMesh in the byte encoding of byte_stream.h (positions, normals, indices, scalp weights), for the
// disk cache's keys and values of this build. readHeadMesh throws hp::Error for a short or malformed stream and
// for a mesh whose arrays disagree (requireMeshShape, head_mesh.h), so what it returns can be drawn.
#include "engine/core/byte_stream.h"
#include "engine/core/hair/hair_asset.h"

namespace hp {
void writeHeadMesh(ByteWriter& out, const HeadMesh& mesh);
HeadMesh readHeadMesh(ByteReader& in);
}  // namespace hp
