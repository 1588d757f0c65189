#pragma once
// Contract: the SVG of `hairpipe bench --plot`: GPU ms per pass (y) against render strand count (x),
// one polyline per pass and raster path (colour = pass, dash = path), with a legend. Pure text.
#include <string>
#include <vector>

#include "samples/cli/bench_frame.h"

namespace hp::cli {
std::string benchPlotSvg(const std::vector<FrameResult>& results);
std::string frameCaseName(const FrameCase& c);  // "compute", "graphics msaa4", ...
}  // namespace hp::cli
