#pragma once
// Contract: converts guides, or render strands, to .hair data for writeHairFile. Render strands are
// the paper's interpolation applied to the guide particles (K_j = X1 A_j + X2 B_j + X3 C_j, no
// tessellation), so each has particlesPerGuide points. The segments array is omitted (all strands
// have the same count: default_segments says it), points are the only array.
#include <string>

#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/strand_topology.h"

namespace hp {
HairFileData guidesToHair(const GuideSet& guides, const std::string& info = "hairpipe guides");
HairFileData renderStrandsToHair(const GuideSet& guides, const InterpolationTopology& topology,
                                 const std::string& info = "hairpipe render strands");
}  // namespace hp
