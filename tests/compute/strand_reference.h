#pragma once
// Double-precision CPU references of the tessellate and interpolate passes (docs/THEORY.md §1.3-1.4), written
// from the definitions rather than from the shaders, plus helpers that run the GPU passes for tests.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "compute/strands/interpolate_pass.h"
#include "compute/strands/strand_buffers.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/strand_topology.h"

namespace hp::test {
// Curves of `vertices` points each, back to back.
struct RefCurves {
  std::uint32_t vertices = 0;
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> tangents;  // unit
};

// Vertex index of particle i: round-half-up of i (Q-1)/(P-1).
std::vector<std::uint32_t> refParticleVertices(std::uint32_t particles, std::uint32_t vertices);
// Cubic Bezier chain through every guide's particles, sampled at Q vertices.
RefCurves refTessellate(const GuideSet& guides, std::uint32_t vertices);
// K_j = X1 A_j + X2 B_j + X3 C_j over the smoothed guides, tangents blended and renormalised.
RefCurves refInterpolate(const RefCurves& smoothed, const InterpolationTopology& topology);
// Float GPU results as double curves.
RefCurves toCurves(const compute::StrandData& data, std::uint32_t vertices);
// Length of each guide's particle polyline.
std::vector<double> guideLengths(const GuideSet& guides);

// The passes' outputs for one run on the rest pose of `asset`.
struct GpuStrands {
  compute::StrandLayout layout;
  compute::StrandData guides;   // smoothed guides
  compute::StrandData strands;  // render strands
};
GpuStrands runStrandPasses(const vk::Context& ctx, const HairAsset& asset, const compute::StrandOptions& options,
                           compute::InterpolateWalk walk = compute::InterpolateWalk::Auto,
                           const GroomSettings& groom = {});

// "1.23e-07": for RecordProperty.
std::string sci(double value);

// Small hand-made assets: a fan of `guides` bent, non-uniformly spaced guides around the origin, and
// a triangle fan topology with `perTriangle` strands per triangle.
HairAsset makeTestAsset(std::uint32_t guides, std::uint32_t particles, std::uint32_t perTriangle);
}  // namespace hp::test
