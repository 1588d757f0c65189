#pragma once
// Contract: a contact sheet of an animation: equally sized RGBA frames laid out left to right, top to
// bottom, `columns` per row, separated by a 2-pixel dark gutter. sheetFrames() picks which of a
// sequence's frames go on it (at most `tiles`, evenly spread, the first and last included). Host only;
// throws hp::Error for no frames, frames of different sizes or a zero column count.
#include <cstdint>
#include <span>
#include <vector>

#include "samples/tools/png_file.h"

namespace hp {
RgbaImage contactSheet(std::span<const RgbaImage> frames, std::uint32_t columns);
// The 1-based frame numbers of a `frames`-long sequence that a sheet of `tiles` shows.
std::vector<std::uint32_t> sheetFrames(std::uint32_t frames, std::uint32_t tiles);
}  // namespace hp
