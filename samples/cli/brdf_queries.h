#pragma once
// Contract: the `hairpipe brdf` query table. One row per line, `lx,ly,lz,vx,vy,vz,tx,ty,tz` (L toward
// the light, V toward the eye, T the tangent), any finite non-zero lengths (normalised here, in double).
// A first line without any number is a header; blank lines are skipped. Any bad input (empty, wrong
// column count, non-numeric, NaN/Inf, out of range, zero-length vector) is an hp::Error naming the
// source and line and quoting at most a short excerpt of the field.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/render/brdf_evaluator.h"

namespace hp::cli {
inline constexpr const char* kBrdfRowFormat = "lx,ly,lz,vx,vy,vz,tx,ty,tz";

std::vector<render::BrdfQuery> parseBrdfQueries(std::string_view text, const std::string& source);
std::vector<render::BrdfQuery> readBrdfQueries(const std::filesystem::path& path);
}  // namespace hp::cli
