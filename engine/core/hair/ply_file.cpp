// Stanford PLY meshes: header, then each element's records in order.
#include "engine/core/hair/ply_file.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr std::uint64_t kMaxPolygonCorners = 1024;

enum class Format { Ascii, Little, Big };
enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

struct Property {
  std::string name;
  Type type = Type::F32;
  bool list = false;
  Type countType = Type::U8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

std::size_t sizeOf(Type t) {
  constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[int(t)];
}

bool parseType(std::string_view s, Type& t) {
  constexpr std::pair<std::string_view, Type> names[] = {
      {"char", Type::I8},   {"int8", Type::I8},     {"uchar", Type::U8},   {"uint8", Type::U8},
      {"short", Type::I16}, {"int16", Type::I16},   {"ushort", Type::U16}, {"uint16", Type::U16},
      {"int", Type::I32},   {"int32", Type::I32},   {"uint", Type::U32},   {"uint32", Type::U32},
      {"float", Type::F32}, {"float32", Type::F32}, {"double", Type::F64}, {"float64", Type::F64}};
  for (const auto& [name, type] : names)
    if (s == name) return t = type, true;
  return false;
}

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t dataStart = 0;
};

void parseHeaderLine(const std::vector<std::string_view>& w, Header& h, const std::string& where) {
  if (w[0] == "format") {
    if (w.size() != 3 || w[2] != "1.0") throw Error(where + "unsupported format line");
    if (w[1] == "ascii") h.format = Format::Ascii;
    else if (w[1] == "binary_little_endian") h.format = Format::Little;
    else if (w[1] == "binary_big_endian") h.format = Format::Big;
    else throw Error(where + "unknown format '" + excerpt(w[1]) + "'");
  } else if (w[0] == "element") {
    std::uint64_t n = 0;
    if (w.size() != 3 || std::from_chars(w[2].data(), w[2].data() + w[2].size(), n).ec != std::errc())
      throw Error(where + "an element needs a name and a count");
    h.elements.push_back({std::string(w[1]), n, {}});
  } else if (w[0] == "property") {
    if (h.elements.empty()) throw Error(where + "a property before any element");
    Property p;
    const bool list = w.size() == 5 && w[1] == "list";
    if (!(list || w.size() == 3) || !parseType(w[list ? 3 : 1], p.type) || (list && !parseType(w[2], p.countType)))
      throw Error(where + "a property needs a known type and a name");
    if (list && (p.countType == Type::F32 || p.countType == Type::F64)) throw Error(where + "a list counted by a float");
    p.list = list;
    p.name = std::string(w.back());
    h.elements.back().properties.push_back(p);
  } else if (w[0] != "comment" && w[0] != "obj_info") {
    throw Error(where + "unknown header line '" + excerpt(w[0]) + "'");
  }
}

Header parseHeader(std::string_view text, const std::string& source) {
  if (text.substr(0, 4) != "ply\n" && text.substr(0, 5) != "ply\r\n") throw Error(source + ": not a PLY file (no 'ply' line)");
  Header h;
  std::size_t at = text.find('\n') + 1, line = 1;
  bool formatSeen = false;
  while (true) {
    const std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos || end > kMaxHeaderBytes)
      throw Error(source + ": no 'end_header' in the first " + std::to_string(kMaxHeaderBytes) + " bytes");
    ++line;
    const auto w = splitWords(text.substr(at, end - at));
    at = end + 1;
    if (w.empty()) continue;
    if (w[0] == "end_header") break;
    formatSeen |= w[0] == "format";
    parseHeaderLine(w, h, source + ": header line " + std::to_string(line) + ": ");
  }
  if (!formatSeen) throw Error(source + ": the header names no format");
  h.dataStart = at;
  return h;
}

// Reads the values after the header, ascii or binary, each checked against what is left.
class Values {
 public:
  Values(std::span<const std::byte> data, Format format, const std::string& source)
      : data_(data), format_(format), source_(source) {}
  std::uint64_t left() const { return data_.size() - at_; }
  // The smallest bytes a value of type t takes.
  std::size_t minBytes(Type t) const { return format_ == Format::Ascii ? 2 : sizeOf(t); }
  double next(Type t, const std::string& what) { return format_ == Format::Ascii ? nextText(t, what) : nextBinary(t, what); }

 private:
  double nextText(Type t, const std::string& what) {
    const char* p = reinterpret_cast<const char*>(data_.data());
    while (at_ < data_.size() && std::strchr(" \t\r\n", p[at_]) && p[at_] != '\0') ++at_;
    std::size_t end = at_;
    while (end < data_.size() && !std::strchr(" \t\r\n", p[end])) ++end;
    if (end == at_) throw Error(source_ + ": the file ends before " + what);
    double v = 0.0;
    const auto r = std::from_chars(p + at_, p + end, v);
    if (r.ec != std::errc() || r.ptr != p + end) throw Error(source_ + ": " + what + " is not a number: '" + excerpt({p + at_, end - at_}) + "'");
    at_ = end;
    if (t != Type::F32 && t != Type::F64 && v != std::floor(v)) throw Error(source_ + ": " + what + " is not an integer");
    return v;
  }
  double nextBinary(Type t, const std::string& what) {
    const std::size_t n = sizeOf(t);
    if (n > left()) throw Error(source_ + ": the file ends before " + what);
    unsigned char b[8];
    std::memcpy(b, data_.data() + at_, n);
    at_ += n;
    if ((format_ == Format::Big) == (std::endian::native == std::endian::little)) std::reverse(b, b + n);
    switch (t) {
      case Type::I8: return double(std::int8_t(b[0]));
      case Type::U8: return double(b[0]);
      case Type::I16: return double(load<std::int16_t>(b));
      case Type::U16: return double(load<std::uint16_t>(b));
      case Type::I32: return double(load<std::int32_t>(b));
      case Type::U32: return double(load<std::uint32_t>(b));
      case Type::F32: return double(load<float>(b));
      case Type::F64: return load<double>(b);
    }
    return 0.0;
  }
  template <typename T>
  static T load(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof(T));
    return v;
  }

  std::span<const std::byte> data_;
  Format format_;
  const std::string& source_;
  std::uint64_t at_ = 0;
};

std::uint64_t minRecordBytes(const Element& e, const Values& in) {
  std::uint64_t bytes = 0;
  for (const auto& p : e.properties) bytes += in.minBytes(p.list ? p.countType : p.type);
  return std::max<std::uint64_t>(bytes, 1);
}

int find(const Element& e, std::string_view name, bool list) {
  for (std::size_t i = 0; i < e.properties.size(); ++i)
    if (e.properties[i].name == name && e.properties[i].list == list) return int(i);
  return -1;
}

struct Layout {
  int xyz[3] = {-1, -1, -1}, normal[3] = {-1, -1, -1}, indices = -1;
};

// One record: every property's values, the ones hairpipe keeps stored in the mesh.
void readRecord(Values& in, const Element& e, const Layout& l, std::uint64_t r, const ModelTransform& tr, CharacterMesh& m) {
  const bool vertex = e.name == "vertex", face = e.name == "face";
  double xyz[3] = {}, n[3] = {};
  std::vector<std::uint32_t> corners;
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const Property& p = e.properties[i];
    const std::string what = e.name + " " + std::to_string(r) + "'s " + p.name;
    if (!p.list) {
      const double v = in.next(p.type, what);
      for (int k = 0; k < 3; ++k) {
        if (vertex && l.xyz[k] == int(i)) xyz[k] = v;
        if (vertex && l.normal[k] == int(i)) n[k] = v;
      }
      continue;
    }
    const double count = in.next(p.countType, what + " count");  // an integer type (the header refuses others)
    const bool kept = face && l.indices == int(i);
    if (kept && (count < 3 || count > double(kMaxPolygonCorners)))
      throw Error(what + " count " + numberText(count) + " is outside 3.." + std::to_string(kMaxPolygonCorners));
    if (count < 0 || count * double(in.minBytes(p.type)) > double(in.left()))
      throw Error("the file ends before " + what + " (" + numberText(count) + " values)");
    for (std::uint64_t k = 0; k < std::uint64_t(count); ++k) {
      const double v = in.next(p.type, what);
      if (!kept) continue;
      if (!(v >= 0 && v < double(m.positions.size()) && v == std::floor(v)))  // NaN and 1.7 name no vertex
        throw Error(what + " refers to vertex " + numberText(v) + " of " + std::to_string(m.positions.size()));
      corners.push_back(std::uint32_t(v));
    }
  }
  if (vertex) {
    m.positions.push_back(tr.applyToPoint(glm::vec3(xyz[0], xyz[1], xyz[2])));
    if (l.normal[0] >= 0) m.normals.push_back(tr.applyToNormal(glm::vec3(n[0], n[1], n[2])));
  }
  if (corners.size() > 2 && m.triangles.size() + corners.size() - 2 > kMaxMeshTriangles)
    throw Error(e.name + " " + std::to_string(r) + " takes the mesh past " + std::to_string(kMaxMeshTriangles) + " triangles");
  for (std::size_t k = 2; k < corners.size(); ++k) m.triangles.push_back({corners[0], corners[k - 1], corners[k]});
}

Layout layoutOf(const Element& e, const std::string& source) {
  Layout l;
  if (e.name == "vertex") {
    const char* names[] = {"x", "y", "z", "nx", "ny", "nz"};
    for (int k = 0; k < 3; ++k) l.xyz[k] = find(e, names[k], false), l.normal[k] = find(e, names[3 + k], false);
    if (l.xyz[0] < 0 || l.xyz[1] < 0 || l.xyz[2] < 0) throw Error(source + ": the vertex element has no x, y and z");
    if (l.normal[0] < 0 || l.normal[1] < 0 || l.normal[2] < 0) l.normal[0] = l.normal[1] = l.normal[2] = -1;
  }
  if (e.name == "face") {
    l.indices = find(e, "vertex_indices", true);
    if (l.indices < 0) l.indices = find(e, "vertex_index", true);
    if (l.indices < 0) throw Error(source + ": the face element has no vertex_indices list");
  }
  return l;
}
}  // namespace

CharacterMesh parsePly(std::span<const std::byte> bytes, const std::string& source, const ModelTransform& transform) {
  transform.validate();
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  const Header h = parseHeader(text, source);
  CharacterMesh m;
  m.source = source;
  m.modelToHead = transform.matrix();
  Values in(bytes.subspan(h.dataStart), h.format, source);
  bool vertices = false;
  for (const Element& e : h.elements) {
    if (e.properties.empty() && e.count > 0) throw Error(source + ": element '" + e.name + "' has no properties");
    if (e.count > in.left() / minRecordBytes(e, in))
      throw Error(source + ": element '" + e.name + "' count " + std::to_string(e.count) + " is more than the file holds");
    if (e.name == "vertex" && (vertices || e.count > kMaxMeshVertices)) throw Error(source + ": a second or too large vertex element");
    if (e.name == "face" && !vertices) throw Error(source + ": the face element comes before the vertex element");
    const Layout l = layoutOf(e, source);
    vertices |= e.name == "vertex";
    try {
      for (std::uint64_t r = 0; r < e.count; ++r) readRecord(in, e, l, r, transform, m);
    } catch (const Error& err) {
      const std::string what = err.what();
      throw Error(what.rfind(source, 0) == 0 ? what : source + ": " + what);
    }
  }
  if (!vertices) throw Error(source + ": no vertex element");
  finishCharacterMesh(m);
  return m;
}

CharacterMesh readPlyFile(const std::filesystem::path& path, const ModelTransform& transform) {
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxMeshFileBytes);
  return parsePly(bytes, path.string(), transform);
}
}  // namespace hp
