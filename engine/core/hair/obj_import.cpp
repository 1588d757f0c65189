#include "engine/core/hair/obj_import.h"

#include "engine/core/hair/tinyobj_config.h"  // its implementation: tinyobj_implementation.cpp

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
struct RawMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normalSums;   // summed file normals per vertex
  std::vector<glm::uvec3> triangles;
  bool allCornersHaveNormals = true;
};

std::string faceLabel(const std::string& file, std::size_t face) {
  return file + ": face " + std::to_string(face + 1);
}

void checkCorner(const tinyobj::index_t& idx, std::size_t vertexCount, const std::string& where) {
  if (idx.vertex_index < 0)
    throw Error(where + ": negative vertex index points before the first vertex");
  if (std::size_t(idx.vertex_index) >= vertexCount)
    throw Error(where + ": vertex index " + std::to_string(idx.vertex_index + 1) + " is out of range (the file has " +
                std::to_string(vertexCount) + " vertices)");
}

void addFace(RawMesh& raw, const tinyobj::attrib_t& attrib, const tinyobj::index_t* corners, unsigned count,
             const std::string& where) {
  if (count < 3) throw Error(where + ": a face needs at least 3 vertices, got " + std::to_string(count));
  const std::size_t normalCount = attrib.normals.size() / 3;
  for (unsigned k = 0; k < count; ++k) {
    checkCorner(corners[k], raw.positions.size(), where);
    for (unsigned j = 0; j < k; ++j)
      if (corners[j].vertex_index == corners[k].vertex_index)
        throw Error(where + ": degenerate face, vertex " + std::to_string(corners[k].vertex_index + 1) +
                    " appears twice");
    int n = corners[k].normal_index;
    if (n < 0 || std::size_t(n) >= normalCount) {
      raw.allCornersHaveNormals = false;
      continue;
    }
    raw.normalSums[corners[k].vertex_index] +=
        glm::vec3(attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]);
  }
  for (unsigned k = 1; k + 1 < count; ++k)
    raw.triangles.emplace_back(corners[0].vertex_index, corners[k].vertex_index, corners[k + 1].vertex_index);
}

// Each undirected edge may border at most two faces.
void checkManifold(const std::vector<glm::uvec3>& triangles, const std::string& file) {
  std::unordered_map<std::uint64_t, int> uses;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      if (++uses[(std::uint64_t(a) << 32) | b] > 2)
        throw Error(file + ": non-manifold edge between vertices " + std::to_string(a + 1) + " and " +
                    std::to_string(b + 1) + " (shared by more than two faces)");
    }
}

void checkFiniteVertices(const std::vector<glm::vec3>& positions, const std::string& file) {
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
      throw Error(file + ": vertex " + std::to_string(i + 1) + " is not finite");
}

// tinyobjloader keeps a face's vertex count in one byte: a face of 256 or more vertices would be misread
// (its count wrapped, the faces after it shifted). Such faces are refused by count before parsing.
constexpr std::size_t kMaxFaceVertices = 255;

// Calls f(number, keyword, rest) for every line (numbered from 1) that starts with a keyword: `rest` is what
// follows the keyword, up to a comment. Lines end at LF, CRLF or a lone CR, as the parser reads them.
template <class F>
void forEachStatement(const std::string& text, F&& f) {
  std::size_t pos = 0, number = 0;
  while (pos < text.size()) {
    std::size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string::npos) end = text.size();
    ++number;
    const std::string_view line = std::string_view(text).substr(pos, end - pos);
    const std::size_t k = line.find_first_not_of(" \t");
    const std::size_t stop = line.find_first_of(" \t", k);
    if (k != std::string_view::npos && line[k] != '#') {
      const std::string_view keyword = line.substr(k, stop == std::string_view::npos ? std::string_view::npos : stop - k);
      const std::string_view rest = stop == std::string_view::npos ? std::string_view() : line.substr(stop);
      f(number, keyword, rest.substr(0, rest.find('#')));
    }
    pos = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
  }
}

// A number's word without a leading '+' (from_chars takes no sign but '-').
std::string_view withoutPlus(std::string_view word) {
  if (word.size() > 1 && word[0] == '+') word.remove_prefix(1);
  return word;
}

// Each corner's vertex index (before any '/') a decimal that fits 32 bits: the parser wrapped
// 99999999999999999999 into some index, and the message spoke of a non-manifold edge.
void checkFaceCorners(const std::vector<std::string_view>& corners, const std::string& where) {
  for (const std::string_view corner : corners) {
    const std::string_view index = withoutPlus(corner.substr(0, corner.find('/')));
    long long value = 0;
    const auto [end, ec] = std::from_chars(index.data(), index.data() + index.size(), value);
    if (ec != std::errc() || end != index.data() + index.size() || value > INT32_MAX || value < -INT32_MAX)
      throw Error(where + ": corner '" + excerpt(corner, 24) + "' is not a vertex index");
  }
}

// 3 to 7 finite numbers (x y z, then w or a colour), read in double precision: a coordinate too small for a
// float is the parser's 0, not an error; one past a float is refused after parsing (checkFiniteVertices).
bool isVertex(const std::vector<std::string_view>& words) {
  bool ok = words.size() >= 3 && words.size() <= 7;
  for (const std::string_view word : words) {
    const std::string_view number = withoutPlus(word);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    ok = ok && ec == std::errc() && end == number.data() + number.size() && std::isfinite(value);
  }
  return ok;
}

// Faces past kMaxFaceVertices corners or with corners that are not indices, and vertex lines that are not
// numbers: the parser reads a missing or unreadable coordinate ("v 0.05", "v abc 0 0", "v nan 0 0") as 0.
void checkStatements(const std::string& text, const std::string& file) {
  std::size_t face = 0;
  forEachStatement(text, [&](std::size_t line, std::string_view keyword, std::string_view rest) {
    if (keyword != "f" && keyword != "v") return;
    const std::vector<std::string_view> w = splitWords(rest);
    if (keyword == "f") {
      if (w.size() > kMaxFaceVertices)
        throw Error(faceLabel(file, face) + " has " + std::to_string(w.size()) + " vertices; at most " +
                    std::to_string(kMaxFaceVertices) + " are supported (split it into smaller polygons)");
      checkFaceCorners(w, faceLabel(file, face++));
    } else if (!isVertex(w)) {
      throw Error(file + ": line " + std::to_string(line) + ": a vertex needs 3 finite coordinates, got 'v" +
                  excerpt(rest, 60) + "'");
    }
  });
}

// Parsed from memory with an empty material text: hairpipe uses no materials, and an `mtllib` line
// must never make it open a file the input names (such as ../../dev/zero).
RawMesh parseRaw(const std::string& text, const std::string& file) {
  checkStatements(text, file);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // indices are validated before any triangulation touches them
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(text, std::string(), config)) {
    std::string err = reader.Error();
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw Error(file + ": " + (err.empty() ? std::string("cannot parse") : excerpt(err, 160)));
  }
  const auto& attrib = reader.GetAttrib();
  RawMesh raw;
  for (std::size_t i = 0; i + 2 < attrib.vertices.size(); i += 3)
    raw.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
  checkFiniteVertices(raw.positions, file);
  raw.normalSums.assign(raw.positions.size(), glm::vec3(0.0f));
  std::size_t face = 0;
  for (const auto& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (unsigned count : shape.mesh.num_face_vertices) {
      if (offset + count > shape.mesh.indices.size()) throw Error(faceLabel(file, face) + ": its corners could not be read");
      addFace(raw, attrib, shape.mesh.indices.data() + offset, count, faceLabel(file, face++));
      offset += count;
    }
    if (offset != shape.mesh.indices.size()) throw Error(file + ": the faces' corners could not be read");
  }
  if (raw.triangles.empty()) throw Error(file + ": no faces");
  checkManifold(raw.triangles, file);
  return raw;
}
}  // namespace

ScalpMesh loadObjScalp(const std::filesystem::path& path, const ModelTransform& transform) {
  transform.validate();
  return parseObjScalp(readInputText(path, kMaxMeshFileBytes), path.string(), transform);
}

ScalpMesh parseObjScalp(const std::string& text, const std::string& source, const ModelTransform& transform) {
  transform.validate();
  RawMesh raw = parseRaw(text, source);
  // Zero-area faces go before compaction, so vertices only they used go too.
  std::uint32_t dropped = dropDegenerateTriangles(raw.positions, raw.triangles);
  if (raw.triangles.empty()) throw Error(source + ": no non-degenerate triangles");
  // Keep only vertices some face uses: one guide grows per scalp vertex.
  std::vector<std::int64_t> remap(raw.positions.size(), -1);
  std::vector<glm::vec3> positions, normals;
  for (auto& t : raw.triangles)
    for (int k = 0; k < 3; ++k) {
      if (remap[t[k]] < 0) {
        remap[t[k]] = static_cast<std::int64_t>(positions.size());
        positions.push_back(transform.applyToPoint(raw.positions[t[k]]));
        normals.push_back(transform.applyToNormal(raw.normalSums[t[k]]));
      }
      t[k] = static_cast<std::uint32_t>(remap[t[k]]);
    }
  if (!raw.allCornersHaveNormals) normals.clear();
  checkHeadSpaceExtent(positions, source);
  ScalpMesh mesh = buildScalpMesh(std::move(positions), std::move(raw.triangles), std::move(normals), source);
  mesh.droppedDegenerateTriangles += dropped;
  return mesh;
}
}  // namespace hp
