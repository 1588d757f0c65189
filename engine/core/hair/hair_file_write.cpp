// Encoding of .hair files and the small HairFileData helpers.
#include <algorithm>
#include <cstring>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/hair_file.h"

namespace hp {
namespace {
template <typename T>
void store(std::vector<std::byte>& out, std::size_t offset, const T& value) {
  std::memcpy(out.data() + offset, &value, sizeof(T));
}

template <typename T>
void append(std::vector<std::byte>& out, const std::vector<T>& values) {
  std::size_t at = out.size();
  out.resize(at + values.size() * sizeof(T));
  if (!values.empty()) std::memcpy(out.data() + at, values.data(), values.size() * sizeof(T));
}
}  // namespace

std::uint32_t HairFileData::arrayFlags() const {
  using namespace hairflags;
  return (segments.empty() ? 0 : kSegments) | kPoints | (thickness.empty() ? 0 : kThickness) |
         (transparency.empty() ? 0 : kTransparency) | (colors.empty() ? 0 : kColors);
}

std::vector<std::uint32_t> HairFileData::strandOffsets() const {
  std::vector<std::uint32_t> offsets(strandCount + 1, 0);
  for (std::uint32_t i = 0; i < strandCount; ++i) offsets[i + 1] = offsets[i] + strandPointCount(i);
  return offsets;
}

std::string HairFileData::infoText() const {
  return std::string(info.data(), std::find(info.begin(), info.end(), '\0'));
}

void HairFileData::setInfoText(const std::string& text) {
  info.fill('\0');
  std::memcpy(info.data(), text.data(), std::min(text.size(), info.size() - 1));
}

std::vector<std::byte> encodeHair(const HairFileData& d) {
  validateHairData(d, "encoding .hair");
  std::vector<std::byte> out(128);
  std::memcpy(out.data(), "HAIR", 4);
  store(out, 4, d.strandCount);
  store(out, 8, d.pointCount());
  store(out, 12, d.arrayFlags());
  store(out, 16, d.defaultSegments);
  store(out, 20, d.defaultThickness);
  store(out, 24, d.defaultTransparency);
  store(out, 28, d.defaultColor);
  std::memcpy(out.data() + 40, d.info.data(), d.info.size());
  out.reserve(128 + d.segments.size() * 2 + d.points.size() * 32);
  append(out, d.segments);
  append(out, d.points);
  append(out, d.thickness);
  append(out, d.transparency);
  append(out, d.colors);
  return out;
}

void writeHairFile(const std::filesystem::path& path, const HairFileData& data) {
  writeFileAtomically(path, encodeHair(data));
}
}  // namespace hp
