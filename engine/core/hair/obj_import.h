#pragma once
// Contract: reads a Wavefront OBJ as a scalp mesh (tinyobjloader parses; this file validates). All
// shapes are merged; polygons are fan-triangulated here (after their indices are checked). Refused
// with hp::Error naming the file: parse errors, a vertex index outside the file, a non-finite vertex (including a negative
// relative index that points before the first vertex), faces with fewer than 3 vertices or a repeated
// vertex, an edge shared by more than two faces (non-manifold), no faces at all. Zero-area faces are
// dropped and counted (ScalpMesh::droppedDegenerateTriangles); vertices used by no face are removed.
// Normals come from the file when every face corner has one, else they are computed.
#include <filesystem>

#include "engine/core/hair/model_transform.h"
#include "engine/core/hair/scalp_mesh.h"

namespace hp {
ScalpMesh loadObjScalp(const std::filesystem::path& path, const ModelTransform& transform = {});
// The same from OBJ text already in memory; `source` names it in messages. Material libraries
// (`mtllib`) are never opened: hairpipe reads geometry only.
ScalpMesh parseObjScalp(const std::string& text, const std::string& source, const ModelTransform& transform = {});
}  // namespace hp
