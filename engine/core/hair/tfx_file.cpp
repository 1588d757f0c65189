// Decoding and validation of TressFX .tfx files (docs/THEORY.md §8.2).
#include "engine/core/hair/tfx_file.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
static_assert(std::endian::native == std::endian::little, ".tfx is little-endian; so is every target");

namespace {
// Header field byte positions.
enum : std::size_t {
  kVersion = 0, kStrands = 4, kVerticesPerStrand = 8, kOffPositions = 12, kOffStrandUV = 16,
  kOffVertexUV = 20, kOffThickness = 24, kOffColors = 28
};

std::uint32_t loadU32(std::span<const std::byte> bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// The array at the header's offset field, checked against the file: count elements of T.
template <typename T>
std::vector<T> loadArray(std::span<const std::byte> bytes, std::size_t field, const char* name, std::uint64_t count,
                         bool required, const std::string& source) {
  const std::uint32_t offset = loadU32(bytes, field);
  if (offset == 0) {
    if (required) throw Error(source + ": " + name + " is 0: the file has no vertex positions");
    return {};
  }
  if (offset < kTfxHeaderSize)
    throw Error(source + ": " + name + " " + std::to_string(offset) + " points into the 160-byte header");
  const std::uint64_t size = count * sizeof(T);  // count < 2^38, so no overflow
  if (std::uint64_t(offset) + size > bytes.size())
    throw Error(source + ": " + name + " " + std::to_string(offset) + " + " + std::to_string(size) +
                " bytes runs past the end of the file (" + std::to_string(bytes.size()) + " bytes)");
  std::vector<T> out(count);
  std::memcpy(out.data(), bytes.data() + offset, size);
  return out;
}

bool finite(const glm::vec2& v) { return std::isfinite(v.x) && std::isfinite(v.y); }
bool finite(const glm::vec4& v) { return finite(glm::vec2(v)) && finite(glm::vec2(v.z, v.w)); }

// "vertex V of strand S" for per-vertex arrays, "strand S" for per-strand ones.
std::string element(std::size_t i, std::uint32_t perStrand) {
  return perStrand == 1 ? "strand " + std::to_string(i)
                        : "vertex " + std::to_string(i % perStrand) + " of strand " + std::to_string(i / perStrand);
}

template <typename T>
void checkFinite(const std::vector<T>& values, const char* name, std::uint32_t perStrand, const std::string& source) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!finite(values[i])) throw Error(source + ": " + name + ": " + element(i, perStrand) + " is not finite");
}

// Every value finite; inverse masses and thicknesses not negative.
void checkValues(const TfxData& d, const std::string& source) {
  const std::uint32_t vps = d.verticesPerStrand;
  for (std::size_t i = 0; i < d.positions.size(); ++i) {
    const glm::vec4& p = d.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Error(source + ": positions: " + element(i, vps) + " is not finite");
    if (!(p.w >= 0.0f) || !std::isfinite(p.w))
      throw Error(source + ": positions: the inverse mass (w) of " + element(i, vps) + " is negative or not finite");
  }
  checkFinite(d.strandUVs, "strand UVs", 1, source);
  checkFinite(d.vertexUVs, "vertex UVs", vps, source);
  checkFinite(d.vertexColors, "vertex colours", vps, source);
  for (std::size_t i = 0; i < d.strandThickness.size(); ++i)
    if (!(d.strandThickness[i] >= 0.0f) || !std::isfinite(d.strandThickness[i]))
      throw Error(source + ": strand thickness: " + element(i, 1) + " is negative or not finite");
}

template <typename T>
void appendArray(std::vector<std::byte>& out, std::size_t field, const std::vector<T>& values) {
  if (values.empty()) return;
  const auto offset = static_cast<std::uint32_t>(out.size());
  std::memcpy(out.data() + field, &offset, 4);
  const auto* p = reinterpret_cast<const std::byte*>(values.data());
  out.insert(out.end(), p, p + values.size() * sizeof(T));
}
}  // namespace

TfxData decodeTfx(std::span<const std::byte> bytes, const std::string& source) {
  if (bytes.size() < kTfxHeaderSize)
    throw Error(source + ": short header: " + std::to_string(bytes.size()) + " bytes, a .tfx header has 160");
  TfxData d;
  std::memcpy(&d.version, bytes.data() + kVersion, 4);
  if (!std::isfinite(d.version)) throw Error(source + ": version is not a finite number");
  d.strandCount = loadU32(bytes, kStrands);
  d.verticesPerStrand = loadU32(bytes, kVerticesPerStrand);
  if (d.strandCount == 0) throw Error(source + ": numHairStrands is 0");
  if (d.verticesPerStrand < 2 || d.verticesPerStrand > 64)
    throw Error(source + ": numVerticesPerStrand " + std::to_string(d.verticesPerStrand) + " is outside 2..64");
  const std::uint64_t vertices = std::uint64_t(d.strandCount) * d.verticesPerStrand;
  d.positions = loadArray<glm::vec4>(bytes, kOffPositions, "offsetVertexPosition", vertices, true, source);
  d.strandUVs = loadArray<glm::vec2>(bytes, kOffStrandUV, "offsetStrandUV", d.strandCount, false, source);
  d.vertexUVs = loadArray<glm::vec2>(bytes, kOffVertexUV, "offsetVertexUV", vertices, false, source);
  d.strandThickness = loadArray<float>(bytes, kOffThickness, "offsetStrandThickness", d.strandCount, false, source);
  d.vertexColors = loadArray<glm::vec4>(bytes, kOffColors, "offsetVertexColor", vertices, false, source);
  checkValues(d, source);
  return d;
}

// Through the bounded door every reader uses (engine/core/hair/input_file.h): a regular file within the size
// limit, its path in every message (a FIFO, /dev/zero or a folder is refused before reading).
TfxData readTfxFile(const std::filesystem::path& path) {
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxHairFileBytes);
  return decodeTfx(bytes, path.string());
}

std::vector<std::byte> encodeTfx(const TfxData& d) {
  std::vector<std::byte> out(kTfxHeaderSize, std::byte{0});
  std::memcpy(out.data() + kVersion, &d.version, 4);
  std::memcpy(out.data() + kStrands, &d.strandCount, 4);
  std::memcpy(out.data() + kVerticesPerStrand, &d.verticesPerStrand, 4);
  appendArray(out, kOffPositions, d.positions);
  appendArray(out, kOffStrandUV, d.strandUVs);
  appendArray(out, kOffVertexUV, d.vertexUVs);
  appendArray(out, kOffThickness, d.strandThickness);
  appendArray(out, kOffColors, d.vertexColors);
  return out;
}

HairFileData tfxToHair(const TfxData& d) {
  HairFileData h;
  h.strandCount = d.strandCount;
  h.defaultSegments = d.verticesPerStrand - 1;
  h.points.reserve(d.positions.size());
  for (const auto& p : d.positions) h.points.emplace_back(p);
  h.setInfoText("TressFX " + std::to_string(d.version).substr(0, 3));
  return h;
}
}  // namespace hp
