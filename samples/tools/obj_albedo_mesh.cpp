#include "samples/tools/obj_albedo_mesh.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/error.h"
#include "engine/hair/atomic_write.h"

namespace hp {
namespace {
constexpr std::size_t kMaxVertices = 1u << 24;

void appendLine(std::string& out, const char* fmt, float a, float b, float c) {
  char line[128];
  std::snprintf(line, sizeof line, fmt, double(a), double(b), double(c));
  out += line;
}

struct ObjLineReader {
  const std::filesystem::path& path;
  std::size_t line = 0;
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(path.string() + ":" + std::to_string(line) + ": " + what);
  }
  glm::vec3 vec3(std::istringstream& in) const {
    glm::vec3 v;
    if (!(in >> v.x >> v.y >> v.z) || !std::isfinite(v.x + v.y + v.z)) fail("expected three finite numbers");
    return v;
  }
  std::uint32_t corner(const std::string& token, std::size_t vertices) const {
    const auto slash = token.find("//");
    std::size_t used = 0;
    unsigned long v = 0, n = 0;
    try {
      v = std::stoul(token.substr(0, slash), &used);
      if (slash == std::string::npos || used != slash) fail("face corners must be written a//a");
      n = std::stoul(token.substr(slash + 2));
    } catch (const std::logic_error&) {
      fail("bad face corner '" + token + "'");
    }
    if (v != n) fail("face corner '" + token + "': the normal index must equal the vertex index");
    if (v < 1 || v > vertices) fail("face corner '" + token + "' refers to a vertex that is not defined");
    return std::uint32_t(v - 1);
  }
};
}  // namespace

void writeAlbedoObj(const std::filesystem::path& path, const AlbedoMesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size() || mesh.albedo.size() != mesh.positions.size() ||
      mesh.indices.size() % 3 != 0)
    throw Error("writeAlbedoObj: positions, normals and albedo must have one entry per vertex, indices whole triangles");
  std::string text = "# hairpipe frame export: head mesh, world space, metres; v x y z albedo_r albedo_g albedo_b\n";
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i], a = mesh.albedo[i];
    char line[256];
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z),
                  double(a.x), double(a.y), double(a.z));
    text += line;
  }
  for (const glm::vec3& n : mesh.normals) appendLine(text, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    char line[96];
    std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", mesh.indices[t] + 1, mesh.indices[t] + 1,
                  mesh.indices[t + 1] + 1, mesh.indices[t + 1] + 1, mesh.indices[t + 2] + 1, mesh.indices[t + 2] + 1);
    text += line;
  }
  writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

AlbedoMesh readAlbedoObj(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open '" + path.string() + "'");
  AlbedoMesh mesh;
  ObjLineReader r{path};
  std::vector<std::string> faces;
  std::vector<std::size_t> faceLines;
  for (std::string text; std::getline(in, text);) {
    ++r.line;
    std::istringstream s(text);
    std::string tag;
    if (!(s >> tag) || tag[0] == '#') continue;
    if (tag == "v") {
      mesh.positions.push_back(r.vec3(s));
      mesh.albedo.push_back(r.vec3(s));
    } else if (tag == "vn") {
      mesh.normals.push_back(r.vec3(s));
    } else if (tag == "f") {
      faces.push_back(text);
      faceLines.push_back(r.line);
    } else {
      r.fail("unexpected '" + tag + "' (a frame export's head holds only v, vn and f)");
    }
    if (mesh.positions.size() > kMaxVertices) r.fail("more than 16M vertices");
  }
  if (mesh.normals.size() != mesh.positions.size()) throw Error(path.string() + ": needs one normal per vertex");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    r.line = faceLines[i];
    std::istringstream s(faces[i]);
    std::string tag, a, b, c, extra;
    s >> tag >> a >> b >> c;
    if (c.empty() || (s >> extra)) r.fail("faces must be triangles");
    for (const std::string* t : {&a, &b, &c}) mesh.indices.push_back(r.corner(*t, mesh.positions.size()));
  }
  if (mesh.indices.empty()) throw Error(path.string() + ": the head has no triangles");
  return mesh;
}
}  // namespace hp
