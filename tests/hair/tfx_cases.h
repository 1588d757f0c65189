#pragma once
// The .tfx files the tests know: a small valid file with every optional array, and each corruption
// with the words its refusal must contain. tfx_file_test checks every refusal, and the seed corpus of
// the .tfx fuzzer (tests/fuzz/corpus/fuzz_tfx/) is exactly these files (a test keeps it so).
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "engine/core/hair/tfx_file.h"

namespace hp::test {
struct TfxCase {
  std::string name;          // file name in the seed corpus, without ".tfx"
  std::vector<std::byte> bytes;
  std::string refusal;       // empty: a valid file
};

// 10 strands x 8 vertices hanging from the top of a 10 cm sphere, with strand and vertex UVs,
// thickness and vertex colours (3,480 bytes).
inline TfxData smallTfx() {
  TfxData d;
  d.strandCount = 10;
  d.verticesPerStrand = 8;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float a = 0.7f * float(s), y = 1.0f - 0.05f * float(s), r = std::sqrt(1.0f - y * y);
    const glm::vec3 root(10.0f * r * std::cos(a), 10.0f * y, 10.0f * r * std::sin(a));
    for (std::uint32_t k = 0; k < d.verticesPerStrand; ++k) {
      d.positions.emplace_back(root + glm::vec3(0.1f * float(k), -2.0f * float(k), 0.0f), k < 2 ? 0.0f : 1.0f);
      d.vertexUVs.emplace_back(float(s) / 10.0f, float(k) / 7.0f);
      d.vertexColors.emplace_back(0.3f, 0.2f, 0.1f + 0.01f * float(k), 1.0f);
    }
    d.strandUVs.emplace_back(float(s) / 10.0f, 0.5f);
    d.strandThickness.push_back(0.5f + 0.01f * float(s));
  }
  return d;
}

namespace detail {
inline std::vector<std::byte> withU32(std::vector<std::byte> b, std::size_t at, std::uint32_t v) {
  std::memcpy(b.data() + at, &v, 4);
  return b;
}
inline std::vector<std::byte> withF32(std::vector<std::byte> b, std::size_t at, float v) {
  std::memcpy(b.data() + at, &v, 4);
  return b;
}
inline std::uint32_t u32At(const std::vector<std::byte>& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}
}  // namespace detail

inline std::vector<TfxCase> tfxCases() {
  using namespace detail;
  const std::vector<std::byte> good = encodeTfx(smallTfx());
  const auto size = std::uint32_t(good.size());
  const std::uint32_t positions = u32At(good, 12), strandUV = u32At(good, 16), vertexUV = u32At(good, 20),
                      thickness = u32At(good, 24), colors = u32At(good, 28);
  TfxData bare = smallTfx();  // positions only
  bare.strandUVs.clear(), bare.vertexUVs.clear(), bare.strandThickness.clear(), bare.vertexColors.clear();
  const float nan = std::nanf(""), inf = INFINITY;
  return {
      {"valid", good, ""},
      {"valid_positions_only", encodeTfx(bare), ""},
      {"short_header", std::vector<std::byte>(good.begin(), good.begin() + 100), "short header"},
      {"zero_strands", withU32(good, 4, 0), "numHairStrands is 0"},
      {"vertices_per_strand_0", withU32(good, 8, 0), "numVerticesPerStrand"},
      {"vertices_per_strand_1", withU32(good, 8, 1), "numVerticesPerStrand"},
      {"vertices_per_strand_65", withU32(good, 8, 65), "numVerticesPerStrand"},
      {"vertices_per_strand_max", withU32(good, 8, 0xffffffffu), "numVerticesPerStrand"},
      // 4G strands x 8 vertices: far past the file, no overflow, no allocation.
      {"huge_strand_count", withU32(good, 4, 0xffffffffu), "offsetVertexPosition"},
      {"no_positions", withU32(good, 12, 0), "offsetVertexPosition is 0"},
      {"positions_past_end", withU32(good, 12, 0xfffffff0u), "offsetVertexPosition 4294967280"},
      {"positions_in_header", withU32(good, 12, 8), "points into the 160-byte header"},
      {"strand_uv_past_end", withU32(good, 16, size - 4), "offsetStrandUV"},
      {"vertex_uv_past_end", withU32(good, 20, size - 100), "offsetVertexUV"},
      {"thickness_past_end", withU32(good, 24, 0xffffffffu), "offsetStrandThickness"},
      {"colors_past_end", withU32(good, 28, size - 100), "offsetVertexColor"},
      {"truncated", std::vector<std::byte>(good.begin(), good.end() - 1), "past the end of the file"},
      {"nan_position", withF32(good, positions + 16 * (2 * 8 + 5) + 4, nan), "positions: vertex 5 of strand 2 is not finite"},
      {"negative_inverse_mass", withF32(good, positions + 16 * 3 + 12, -1.0f), "inverse mass (w) of vertex 3 of strand 0"},
      {"inf_version", withF32(good, 0, inf), "version"},
      {"nan_strand_uv", withF32(good, strandUV + 8 * 4, nan), "strand UVs: strand 4 is not finite"},
      {"inf_vertex_uv", withF32(good, vertexUV + 8 * 9 + 4, inf), "vertex UVs: vertex 1 of strand 1 is not finite"},
      {"negative_thickness", withF32(good, thickness + 4 * 7, -0.5f), "strand thickness: strand 7 is negative"},
      {"nan_color", withF32(good, colors + 16 * 79 + 12, nan), "vertex colours: vertex 7 of strand 9 is not finite"},
  };
}
}  // namespace hp::test
