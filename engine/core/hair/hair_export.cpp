#include "engine/core/hair/hair_export.h"

#include "engine/core/error.h"

namespace hp {
namespace {
HairFileData uniformStrands(std::uint32_t strands, std::uint32_t pointsPerStrand, const std::string& info) {
  if (strands == 0) throw Error("export .hair: no strands");
  HairFileData d;
  d.strandCount = strands;
  d.defaultSegments = pointsPerStrand - 1;
  d.setInfoText(info);
  return d;
}
}  // namespace

HairFileData guidesToHair(const GuideSet& guides, const std::string& info) {
  HairFileData d = uniformStrands(guides.guideCount(), guides.particlesPerGuide, info);
  d.points = guides.positions;
  return d;
}

HairFileData renderStrandsToHair(const GuideSet& guides, const InterpolationTopology& topology,
                                 const std::string& info) {
  const std::uint32_t P = guides.particlesPerGuide;
  HairFileData d = uniformStrands(static_cast<std::uint32_t>(topology.strands.size()), P, info);
  d.points.reserve(topology.strands.size() * P);
  for (const auto& s : topology.strands) {
    const glm::uvec3& t = topology.triangles.at(s.triangle);
    auto a = guides.guide(t.x), b = guides.guide(t.y), c = guides.guide(t.z);
    for (std::uint32_t j = 0; j < P; ++j)
      d.points.push_back(s.barycentric.x * a[j] + s.barycentric.y * b[j] + s.barycentric.z * c[j]);
  }
  return d;
}
}  // namespace hp
