// Decoding and validation of TressFX .tfxbone files (docs/THEORY.md §8.3).
#include "engine/core/hair/tfx_bone_file.h"

#include <bit>
#include <cmath>

#include "engine/core/byte_stream.h"
#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
static_assert(std::endian::native == std::endian::little, ".tfxbone is little-endian; so is every target");

namespace {
constexpr std::uint64_t kStrandRecordBytes = 4 + 4 * 8;  // index, then 4 x (bone, weight)

// A bone's name: `length` bytes ending with a NUL, the name up to the first NUL.
std::string takeName(ByteReader& r, std::uint64_t length, const std::string& what, const std::string& source) {
  const std::span<const std::byte> bytes = r.take(length, what);
  const char* p = reinterpret_cast<const char*>(bytes.data());
  if (length == 0 || p[length - 1] != '\0') throw Error(source + ": " + what + " does not end with its NUL");
  return std::string(p);
}

void readBones(ByteReader& r, TfxBoneData& d, const std::string& source) {
  const std::int32_t count = r.get<std::int32_t>("the bone count");
  // Each bone takes at least 9 bytes (index, length, one NUL).
  if (count <= 0 || std::uint64_t(count) * 9 > r.left())
    throw Error(source + ": bone count " + std::to_string(count) + " is not positive or more than the file holds");
  for (std::int32_t b = 0; b < count; ++b) {
    const std::string what = "bone " + std::to_string(b);
    d.boneIndices.push_back(r.get<std::int32_t>(what + "'s index"));
    const std::int32_t length = r.get<std::int32_t>(what + "'s name length");
    if (length <= 0 || std::uint64_t(length) > kTfxBoneMaxNameBytes)
      throw Error(source + ": " + what + "'s name length " + std::to_string(length) + " is outside 1.." +
                  std::to_string(kTfxBoneMaxNameBytes));
    d.boneNames.push_back(takeName(r, std::uint64_t(length), what + "'s name", source));
  }
}

void checkStrand(const TfxStrandSkin& s, std::size_t boneCount, const std::string& what, const std::string& source) {
  float sum = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const std::string pair = what + " influence " + std::to_string(k);
    if (!std::isfinite(s.weights[k]) || s.weights[k] < 0.0f)
      throw Error(source + ": " + pair + " has weight " + std::to_string(s.weights[k]) + " (must be finite and >= 0)");
    if (s.bones[k] < -1 || s.bones[k] >= std::int64_t(boneCount))
      throw Error(source + ": " + pair + " names bone " + std::to_string(s.bones[k]) + ", the file has " +
                  std::to_string(boneCount));
    if (s.bones[k] == -1 && s.weights[k] != 0.0f)
      throw Error(source + ": " + pair + " has no bone (-1) but weight " + std::to_string(s.weights[k]));
    sum += s.weights[k];
  }
  if (!(sum > 0.0f) || !std::isfinite(sum)) throw Error(source + ": " + what + "'s weights sum to " + std::to_string(sum));
}

void readStrands(ByteReader& r, TfxBoneData& d, const std::string& source) {
  const std::int32_t count = r.get<std::int32_t>("the strand count");
  if (count < 0 || std::uint64_t(count) * kStrandRecordBytes != r.left())
    throw Error(source + ": strand count " + std::to_string(count) + " needs " +
                std::to_string(std::int64_t(count) * std::int64_t(kStrandRecordBytes)) + " bytes, the file has " +
                std::to_string(r.left()) + " left");
  d.strands.resize(std::size_t(count));
  for (std::int32_t i = 0; i < count; ++i) {
    TfxStrandSkin& s = d.strands[std::size_t(i)];
    const std::string what = "strand " + std::to_string(i);
    s.strand = r.get<std::int32_t>(what + "'s index");
    for (int k = 0; k < 4; ++k) {
      s.bones[k] = r.get<std::int32_t>(what + "'s bone");
      s.weights[k] = r.get<float>(what + "'s weight");
    }
    checkStrand(s, d.boneNames.size(), what, source);
  }
}

}  // namespace

TfxBoneData decodeTfxBone(std::span<const std::byte> bytes, const std::string& source) {
  ByteReader r(bytes, source);
  TfxBoneData d;
  readBones(r, d, source);
  readStrands(r, d, source);
  return d;
}

TfxBoneData readTfxBoneFile(const std::filesystem::path& path) {
  return decodeTfxBone(readInputBytes(path, kMaxHairFileBytes), path.string());
}

std::vector<std::byte> encodeTfxBone(const TfxBoneData& d) {
  ByteWriter out;
  out.put(std::int32_t(d.boneNames.size()));
  for (std::size_t b = 0; b < d.boneNames.size(); ++b) {
    out.put(b < d.boneIndices.size() ? d.boneIndices[b] : std::int32_t(b));
    out.put(std::int32_t(d.boneNames[b].size() + 1));
    for (char c : d.boneNames[b]) out.put(c);
    out.put('\0');
  }
  out.put(std::int32_t(d.strands.size()));
  for (const TfxStrandSkin& s : d.strands) {
    out.put(s.strand);
    for (int k = 0; k < 4; ++k) {
      out.put(s.bones[k]);
      out.put(s.weights[k]);
    }
  }
  return out.take();
}

std::vector<gpu::SkinWeights> tfxBoneSkinWeights(const TfxBoneData& d, std::uint32_t guideCount,
                                                 const std::string& source) {
  if (d.strands.empty()) throw Error(source + ": the file has no strands");
  if (d.strands.size() > guideCount)
    throw Error(source + ": " + std::to_string(d.strands.size()) + " strands of skinning for " +
                std::to_string(guideCount) + " guides");
  std::vector<gpu::SkinWeights> out(guideCount);
  for (std::uint32_t g = 0; g < guideCount; ++g) {
    const TfxStrandSkin& s = d.strands[std::min<std::size_t>(g, d.strands.size() - 1)];
    const float sum = s.weights[0] + s.weights[1] + s.weights[2] + s.weights[3];
    for (int k = 0; k < 4; ++k) {
      out[g].bones[k] = s.bones[k] < 0 ? 0u : std::uint32_t(s.bones[k]);
      out[g].weights[k] = s.weights[k] / sum;
    }
  }
  return out;
}
}  // namespace hp
