#include "samples/cli/bench_plot.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace hp::cli {
namespace {
constexpr double kW = 900, kH = 520, kLeft = 70, kRight = 230, kTop = 30, kBottom = 50;
const char* kColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b",
                          "#e377c2", "#7f7f7f", "#bcbd22", "#17becf", "#000000", "#aa4499"};
const char* kDashes[] = {"", "6,4", "2,3", "10,3,2,3"};

std::string fmt(const char* f, double a, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a, b);
  return buf;
}
}  // namespace

std::string frameCaseName(const FrameCase& c) {
  const bool defaultScattering = c.lutMode != LutMode::Physical || c.scattering == render::LookSettings{}.scattering;
  const std::string scattering = defaultScattering ? ""
                                 : c.scattering == render::Scattering::Dual      ? ", dual scattering"
                                                                                 : ", single scattering";
  const std::string model = c.lutMode == LutMode::Physical ? std::string() : std::string(", ") + lutModeName(c.lutMode);
  const std::string bounce = c.bounceSamples == gpu::RENDER_BOUNCE_STRAND_SAMPLES
                                 ? ""
                                 : ", bounce x" + std::to_string(c.bounceSamples);
  const std::string shadows = c.shadowStrands == 0 ? "" : ", " + std::to_string(c.shadowStrands) + " shadow strands";
  const std::string shading = model + scattering + bounce + (c.groom ? "" : ", no groom") +
                              (c.skinIndirect ? "" : ", no skin indirect") + shadows;
  if (c.raster == RasterMode::Compute) {
    const std::string head = c.msaa == 4 ? "" : " head msaa" + std::to_string(c.msaa);
    const std::string walk =
        c.fineWalk == compute::FineWalk::Auto ? "" : std::string(", ") + compute::fineWalkName(c.fineWalk) + " fine walk";
    std::ostringstream spacing;
    if (c.shadingSpacing != compute::RasterSettings{}.shadingSpacing) spacing << ", shading spacing " << c.shadingSpacing;
    return (c.skinBounce ? "compute" : "compute, no skin bounce") + head + shading + walk + spacing.str() +
           (c.growLists ? ", grown lists" : "");
  }
  return "graphics msaa" + std::to_string(c.msaa) + shading;
}

std::string benchPlotSvg(const std::vector<FrameResult>& results) {
  std::set<std::string> passes, cases;
  double maxMs = 1e-3, minS = 1e300, maxS = 0;
  for (const FrameResult& r : results) {
    cases.insert(frameCaseName(r.c));
    minS = std::min(minS, double(r.c.strands));
    maxS = std::max(maxS, double(r.c.strands));
    for (const auto& [name, t] : r.passes) {
      if (name == "copy") continue;
      passes.insert(name);
      maxMs = std::max(maxMs, t.medianMs);
    }
  }
  if (maxS <= minS) maxS = minS + 1.0;
  const auto x = [&](double s) { return kLeft + (s - minS) / (maxS - minS) * (kW - kLeft - kRight); };
  const auto y = [&](double ms) { return kH - kBottom - ms / maxMs * (kH - kTop - kBottom); };
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(int(kW)) + "\" height=\"" +
                    std::to_string(int(kH)) + "\" font-family=\"sans-serif\" font-size=\"11\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg += "<text x=\"" + std::to_string(int(kLeft)) + "\" y=\"18\">GPU ms per pass (median) vs render strands</text>\n";
  svg += "<line x1=\"" + fmt("%.1f", kLeft, 0) + "\" y1=\"" + fmt("%.1f", kH - kBottom, 0) + "\" x2=\"" +
         fmt("%.1f", kW - kRight, 0) + "\" y2=\"" + fmt("%.1f", kH - kBottom, 0) + "\" stroke=\"black\"/>\n";
  svg += "<line x1=\"" + fmt("%.1f", kLeft, 0) + "\" y1=\"" + fmt("%.1f", kTop, 0) + "\" x2=\"" + fmt("%.1f", kLeft, 0) +
         "\" y2=\"" + fmt("%.1f", kH - kBottom, 0) + "\" stroke=\"black\"/>\n";
  for (int i = 0; i <= 4; ++i) {
    const double ms = maxMs * i / 4.0, s = minS + (maxS - minS) * i / 4.0;
    svg += "<text x=\"4\" y=\"" + fmt("%.1f", y(ms) + 4, 0) + "\">" + fmt("%.1f ms", ms, 0) + "</text>\n";
    svg += "<text x=\"" + fmt("%.1f", x(s) - 20, 0) + "\" y=\"" + fmt("%.1f", kH - kBottom + 18, 0) + "\">" +
           fmt("%.0f", s, 0) + "</text>\n";
  }
  int p = 0, legend = 0;
  for (const std::string& pass : passes) {
    const char* colour = kColours[p++ % std::size(kColours)];
    int d = 0;
    for (const std::string& name : cases) {
      const char* dash = kDashes[d++ % std::size(kDashes)];
      std::map<double, double> points;
      for (const FrameResult& r : results)
        if (frameCaseName(r.c) == name && r.passes.count(pass)) points[r.c.strands] = r.passes.at(pass).medianMs;
      if (points.empty()) continue;
      std::string line;
      for (const auto& [s, ms] : points) {
        line += fmt("%.1f,%.1f ", x(s), y(ms));
        svg += "<circle cx=\"" + fmt("%.1f", x(s), 0) + "\" cy=\"" + fmt("%.1f", y(ms), 0) + "\" r=\"2.5\" fill=\"" +
               colour + "\"/>\n";
      }
      svg += std::string("<polyline fill=\"none\" stroke=\"") + colour + "\" stroke-dasharray=\"" + dash +
             "\" points=\"" + line + "\"/>\n";
      const double ly = kTop + 14.0 * legend++;
      svg += std::string("<line x1=\"") + fmt("%.1f", kW - kRight + 10, 0) + "\" y1=\"" + fmt("%.1f", ly, 0) +
             "\" x2=\"" + fmt("%.1f", kW - kRight + 34, 0) + "\" y2=\"" + fmt("%.1f", ly, 0) + "\" stroke=\"" + colour +
             "\" stroke-dasharray=\"" + dash + "\"/>\n";
      svg += "<text x=\"" + fmt("%.1f", kW - kRight + 38, 0) + "\" y=\"" + fmt("%.1f", ly + 4, 0) + "\">" + pass +
             " (" + name + ")</text>\n";
    }
  }
  return svg + "</svg>\n";
}
}  // namespace hp::cli
