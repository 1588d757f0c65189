// TressFX .tfxmesh text (docs/THEORY.md §8.4).
#include "engine/core/hair/tfx_mesh_file.h"

#include <charconv>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
// The file's non-comment lines, split into tokens, read front to back without storing them.
class TokenLines {
 public:
  TokenLines(std::string_view text, const std::string& source) : text_(text), source_(source) {}
  // Bytes not read yet: each line left takes at least two of them (a field and its line end, the last aside).
  std::size_t bytesLeft() const { return text_.size() - at_; }
  bool done() {
    skipBlank();
    return at_ >= text_.size();
  }
  // The next line's tokens; exactly `count` of them or the line is refused.
  std::vector<std::string_view> take(std::size_t count, const std::string& what) {
    if (done()) throw Error(source_ + ": the file ends before " + what);
    const std::string_view line = nextLine();
    std::vector<std::string_view> tokens;
    std::size_t at = 0;
    while ((at = line.find_first_not_of(" \t\r", at)) != std::string_view::npos && tokens.size() <= count) {
      const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
      tokens.push_back(line.substr(at, end - at));
      at = end;
    }
    if (tokens.size() != count)
      throw Error(where() + what + " needs " + std::to_string(count) + " fields: '" + excerpt(line) + "'");
    return tokens;
  }
  std::string where() const { return source_ + ": line " + std::to_string(line_) + ": "; }

 private:
  // The line starting at at_ without its comment; `end` is where it ends.
  std::string_view lineHere(std::size_t& end) const {
    end = text_.find('\n', at_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view line = text_.substr(at_, end - at_);
    if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    return line;
  }
  // The next line (the cursor moves past it).
  std::string_view nextLine() {
    std::size_t end = 0;
    const std::string_view line = lineHere(end);
    at_ = end + 1;
    ++line_;
    return line;
  }
  // Past blank and comment-only lines.
  void skipBlank() {
    std::size_t end = 0;
    while (at_ < text_.size() && lineHere(end).find_first_not_of(" \t\r") == std::string_view::npos) {
      at_ = end + 1;
      ++line_;
    }
  }

  std::string_view text_;
  std::size_t at_ = 0, line_ = 0;
  const std::string& source_;
};

template <typename T>
T number(TokenLines& in, std::string_view token, const std::string& what) {
  T v{};
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
  if (ec != std::errc() || end != token.data() + token.size())
    throw Error(in.where() + what + " is not a number: '" + excerpt(token) + "'");
  return v;
}

// "keyword N": N, at most what the bytes left can hold (records of at least `recordBytes`) and `limit`.
std::size_t countLine(TokenLines& in, const char* keyword, std::uint64_t recordBytes, std::uint64_t limit) {
  const auto t = in.take(2, keyword);
  if (t[0] != keyword) throw Error(in.where() + "expected '" + keyword + "', got '" + excerpt(t[0]) + "'");
  const auto n = number<std::int64_t>(in, t[1], keyword);
  if (n < 0 || std::uint64_t(n) > (in.bytesLeft() + 1) / recordBytes || std::uint64_t(n) > limit)
    throw Error(in.where() + keyword + " " + std::to_string(n) + " is negative or more than the file holds (" +
                std::to_string(in.bytesLeft()) + " bytes left)");
  return std::size_t(n);
}

void checkIndex(TokenLines& in, std::string_view token, std::size_t expected, const char* what) {
  if (number<std::int64_t>(in, token, what) != std::int64_t(expected))
    throw Error(in.where() + what + " index " + std::string(excerpt(token)) + " where " + std::to_string(expected) +
                " was expected");
}

void readVertex(TokenLines& in, std::size_t i, std::size_t bones, const ModelTransform& tr, CharacterMesh& m) {
  const auto t = in.take(15, "vertex " + std::to_string(i));
  checkIndex(in, t[0], i, "vertex");
  float f[14];
  for (int k = 0; k < 14; ++k) f[k] = number<float>(in, t[std::size_t(k) + 1], "vertex " + std::to_string(i) + " field " + std::to_string(k + 1));
  m.positions.push_back(tr.applyToPoint({f[0], f[1], f[2]}));
  m.normals.push_back(tr.applyToNormal({f[3], f[4], f[5]}));
  glm::uvec4 joints;
  for (int k = 0; k < 4; ++k) {
    if (!(f[6 + k] >= 0.0f && f[6 + k] < float(bones)) || f[6 + k] != float(int(f[6 + k])))
      throw Error(in.where() + "vertex " + std::to_string(i) + "'s joint " + std::to_string(f[6 + k]) +
                  " is not a bone of the file's " + std::to_string(bones));
    joints[k] = std::uint32_t(f[6 + k]);
  }
  m.joints.push_back(joints);
  m.weights.push_back({f[10], f[11], f[12], f[13]});
}
}  // namespace

CharacterMesh parseTfxMesh(std::string_view text, const std::string& source, const ModelTransform& transform) {
  transform.validate();
  TokenLines in(text, source);
  CharacterMesh m;
  m.source = source;
  m.modelToHead = transform.matrix();
  // The shortest records: "0 b\n" (4 bytes), fifteen one-character fields (30), "0 0 1 2\n" (8).
  const std::size_t bones = countLine(in, "numOfBones", 4, kMaxMeshJoints);
  for (std::size_t b = 0; b < bones; ++b) {
    const auto t = in.take(2, "bone " + std::to_string(b));
    checkIndex(in, t[0], b, "bone");
    m.skeleton.push_back(Joint{std::string(t[1])});
  }
  const std::size_t vertices = countLine(in, "numOfVertices", 30, kMaxMeshVertices);
  m.positions.reserve(vertices);
  for (std::size_t v = 0; v < vertices; ++v) readVertex(in, v, bones, transform, m);
  const std::size_t triangles = countLine(in, "numOfTriangles", 8, kMaxMeshTriangles);
  m.triangles.reserve(triangles);
  for (std::size_t i = 0; i < triangles; ++i) {
    const auto t = in.take(4, "triangle " + std::to_string(i));
    checkIndex(in, t[0], i, "triangle");
    glm::uvec3 tri;
    for (int k = 0; k < 3; ++k) {
      const auto v = number<std::int64_t>(in, t[std::size_t(k) + 1], "triangle " + std::to_string(i));
      if (v < 0 || std::uint64_t(v) >= vertices)
        throw Error(in.where() + "triangle " + std::to_string(i) + " refers to vertex " + std::to_string(v) +
                    " of " + std::to_string(vertices));
      tri[k] = std::uint32_t(v);
    }
    m.triangles.push_back(tri);
  }
  if (!in.done()) throw Error(in.where() + "more lines after the last triangle");
  finishCharacterMesh(m);
  return m;
}

CharacterMesh readTfxMeshFile(const std::filesystem::path& path, const ModelTransform& transform) {
  const std::string text = readInputText(path, kMaxMeshFileBytes);
  return parseTfxMesh(text, path.string(), transform);
}
}  // namespace hp
