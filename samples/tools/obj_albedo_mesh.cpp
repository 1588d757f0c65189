#include "samples/tools/obj_albedo_mesh.h"

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
constexpr std::size_t kMaxVertices = 1u << 24;

// Shortest text that reads back to the same float (std::to_chars), then a separator.
void appendNumber(std::string& out, float v, char after) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
  out += after;
}

void appendIndex(std::string& out, std::uint32_t i, char after) {
  char buf[16];
  const auto r = std::to_chars(buf, buf + sizeof buf, i + 1);
  out.append(buf, r.ptr);
  out += "//";
  out.append(buf, r.ptr);
  out += after;
}

// Reads one line's tokens; every failure names the file and the line.
class LineParser {
 public:
  LineParser(const std::string& source, std::size_t line, std::string_view text)
      : source_(source), line_(line), text_(text) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(source_ + ":" + std::to_string(line_) + ": " + what);
  }
  std::string_view token() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\r')) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < text_.size() && text_[pos_] != ' ' && text_[pos_] != '\t' && text_[pos_] != '\r') ++pos_;
    return text_.substr(start, pos_ - start);
  }
  float number() {
    const std::string_view t = token();
    float v = 0.0f;
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
      fail("expected a finite number, got '" + std::string(t) + "'");
    return v;
  }
  glm::vec3 vec3() { return {number(), number(), number()}; }
  std::uint32_t corner(std::size_t vertices) {
    const std::string_view t = token();
    const std::size_t slash = t.find("//");
    unsigned long v = 0, n = 0;
    const bool ok = slash != std::string_view::npos &&
                    std::from_chars(t.data(), t.data() + slash, v).ptr == t.data() + slash &&
                    std::from_chars(t.data() + slash + 2, t.data() + t.size(), n).ptr == t.data() + t.size();
    if (!ok) fail("face corners must be written a//a, got '" + std::string(t) + "'");
    if (v != n) fail("face corner '" + std::string(t) + "': the normal index must equal the vertex index");
    if (v < 1 || v > vertices) fail("face corner '" + std::string(t) + "' refers to a vertex that is not defined");
    return std::uint32_t(v - 1);
  }
  void end() {
    if (!token().empty()) fail("unexpected text after the values");
  }

 private:
  const std::string& source_;
  std::size_t line_;
  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string albedoObjText(const AlbedoMesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size() || mesh.albedo.size() != mesh.positions.size() ||
      mesh.indices.size() % 3 != 0)
    throw Error("writeAlbedoObj: positions, normals and albedo must have one entry per vertex, indices whole triangles");
  std::string text = "# hairpipe frame export: head mesh, world space, metres; v x y z albedo_r albedo_g albedo_b\n";
  text.reserve(mesh.positions.size() * 160);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i], a = mesh.albedo[i];
    text += "v ";
    for (float v : {p.x, p.y, p.z, a.x, a.y}) appendNumber(text, v, ' ');
    appendNumber(text, a.z, '\n');
  }
  for (const glm::vec3& n : mesh.normals) {
    text += "vn ";
    appendNumber(text, n.x, ' ');
    appendNumber(text, n.y, ' ');
    appendNumber(text, n.z, '\n');
  }
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    text += "f ";
    appendIndex(text, mesh.indices[t], ' ');
    appendIndex(text, mesh.indices[t + 1], ' ');
    appendIndex(text, mesh.indices[t + 2], '\n');
  }
  return text;
}

void writeAlbedoObj(const std::filesystem::path& path, const AlbedoMesh& mesh) {
  const std::string text = albedoObjText(mesh);
  writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

AlbedoMesh readAlbedoObj(const std::filesystem::path& path) {
  return parseAlbedoObj(readInputText(path, kMaxMeshFileBytes), path.string());
}

AlbedoMesh parseAlbedoObj(const std::string& text, const std::string& source) {
  AlbedoMesh mesh;
  std::vector<std::pair<std::size_t, std::string_view>> faces;  // read once every vertex is known
  std::size_t line = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view lineText = std::string_view(text).substr(start, end - start);
    start = end + 1;
    LineParser p(source, ++line, lineText);
    const std::string_view tag = p.token();
    if (tag.empty() || tag[0] == '#') continue;
    if (tag == "v") {
      mesh.positions.push_back(p.vec3());
      mesh.albedo.push_back(p.vec3());
      const glm::vec3& a = mesh.albedo.back();
      if (!(a.x >= 0.0f && a.y >= 0.0f && a.z >= 0.0f && a.x <= 1.0f && a.y <= 1.0f && a.z <= 1.0f))
        p.fail("an albedo must be in [0, 1] in each channel");
      p.end();
    } else if (tag == "vn") {
      mesh.normals.push_back(p.vec3());
      if (!(glm::length(mesh.normals.back()) > 0.0f)) p.fail("a normal must not be zero");
      p.end();
    } else if (tag == "f") {
      faces.emplace_back(line, lineText);
    } else {
      p.fail("unexpected '" + std::string(tag) + "' (a frame export's head holds only v, vn and f)");
    }
    if (mesh.positions.size() > kMaxVertices) p.fail("more than 16M vertices");
  }
  if (mesh.normals.size() != mesh.positions.size()) throw Error(source + ": needs one normal per vertex");
  for (const auto& [number, lineText] : faces) {
    LineParser p(source, number, lineText);
    p.token();  // "f"
    for (int k = 0; k < 3; ++k) mesh.indices.push_back(p.corner(mesh.positions.size()));
    if (!p.token().empty()) p.fail("faces must be triangles");
  }
  // No vertex and no face: the frame had no head (a hair-only frame). Vertices without a face are an error.
  if (mesh.indices.empty() && !mesh.positions.empty()) throw Error(source + ": vertices but no triangles");
  return mesh;
}
}  // namespace hp
