#include "tests/compute/strand_reference.h"

#include <cmath>
#include <cstdio>

#include "samples/tools/strand_dump.h"
#include "engine/vk/barriers.h"
#include "engine/vk/submit.h"

namespace hp::test {
namespace {
glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback) {
  double len = glm::length(v);
  return len > 1e-15 ? v / len : fallback;
}

// Central differences inside, one-sided at the ends.
std::vector<glm::dvec3> particleTangents(const std::vector<glm::dvec3>& p) {
  std::vector<glm::dvec3> t(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, p.size() - 1);
    t[i] = unitOr(p[hi] - p[lo], {0.0, -1.0, 0.0});
  }
  return t;
}

void appendBezier(const glm::dvec3& p0, const glm::dvec3& t0, const glm::dvec3& p1, const glm::dvec3& t1,
                  double u, RefCurves& out) {
  double third = glm::length(p1 - p0) / 3.0;
  glm::dvec3 b[4] = {p0, p0 + t0 * third, p1 - t1 * third, p1};
  double s = 1.0 - u;
  out.positions.push_back(s * s * s * b[0] + 3.0 * s * s * u * b[1] + 3.0 * s * u * u * b[2] + u * u * u * b[3]);
  glm::dvec3 d = 3.0 * (s * s * (b[1] - b[0]) + 2.0 * s * u * (b[2] - b[1]) + u * u * (b[3] - b[2]));
  out.tangents.push_back(unitOr(d, unitOr(glm::mix(t0, t1, u), t0)));
}
}  // namespace

std::vector<std::uint32_t> refParticleVertices(std::uint32_t particles, std::uint32_t vertices) {
  std::vector<std::uint32_t> k(particles);
  for (std::uint32_t i = 0; i < particles; ++i)
    k[i] = static_cast<std::uint32_t>(std::floor(double(i) * (vertices - 1) / (particles - 1) + 0.5));
  return k;
}

RefCurves refTessellate(const GuideSet& guides, std::uint32_t vertices) {
  RefCurves out;
  out.vertices = vertices;
  const std::vector<std::uint32_t> k = refParticleVertices(guides.particlesPerGuide, vertices);
  for (std::uint32_t g = 0; g < guides.guideCount(); ++g) {
    std::vector<glm::dvec3> p;
    for (const glm::vec3& x : guides.guide(g)) p.emplace_back(x);
    std::vector<glm::dvec3> t = particleTangents(p);
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
      std::uint32_t last = (i + 2 == p.size()) ? k[i + 1] : k[i + 1] - 1;  // the tip closes the last segment
      for (std::uint32_t j = k[i]; j <= last; ++j)
        appendBezier(p[i], t[i], p[i + 1], t[i + 1], double(j - k[i]) / (k[i + 1] - k[i]), out);
    }
  }
  return out;
}

RefCurves refInterpolate(const RefCurves& smoothed, const InterpolationTopology& topology) {
  RefCurves out;
  const std::uint32_t q = out.vertices = smoothed.vertices;
  for (const StrandBinding& s : topology.strands) {
    const glm::uvec3 tri = topology.triangles[s.triangle];
    const glm::dvec3 w(s.barycentric);
    for (std::uint32_t j = 0; j < q; ++j) {
      std::size_t a = std::size_t(tri.x) * q + j, b = std::size_t(tri.y) * q + j, c = std::size_t(tri.z) * q + j;
      out.positions.push_back(w.x * smoothed.positions[a] + w.y * smoothed.positions[b] + w.z * smoothed.positions[c]);
      glm::dvec3 t = w.x * smoothed.tangents[a] + w.y * smoothed.tangents[b] + w.z * smoothed.tangents[c];
      out.tangents.push_back(unitOr(t, smoothed.tangents[a]));
    }
  }
  return out;
}

RefCurves toCurves(const compute::StrandData& data, std::uint32_t vertices) {
  RefCurves out;
  out.vertices = vertices;
  for (const glm::vec4& p : data.positions) out.positions.emplace_back(glm::vec3(p));
  for (const glm::vec4& t : data.tangents) out.tangents.emplace_back(glm::vec3(t));
  return out;
}

std::vector<double> guideLengths(const GuideSet& guides) {
  std::vector<double> lengths;
  for (std::uint32_t g = 0; g < guides.guideCount(); ++g) {
    auto p = guides.guide(g);
    double len = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) len += glm::length(glm::dvec3(p[i]) - glm::dvec3(p[i - 1]));
    lengths.push_back(len);
  }
  return lengths;
}

std::string sci(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

GpuStrands runStrandPasses(const vk::Context& ctx, const HairAsset& asset, const compute::StrandOptions& options,
                           compute::InterpolateWalk walk, const GroomSettings& groom) {
  const GuideSet& guides = asset.guides;
  compute::StrandBuffers buffers(ctx, guides.guideCount(), guides.particlesPerGuide, asset.topology, options);
  vk::Buffer particles = compute::uploadGuideParticles(ctx, guides);
  compute::TessellatePass tessellate(ctx, particles, buffers);
  compute::InterpolatePass interpolate(ctx, buffers, nullptr, groom, walk);
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) { compute::recordStrandPasses(ctx, cmd, tessellate, interpolate); },
                    "strand passes test");
  // The smoothed guides' last use was the interpolate pass's read.
  return {buffers.layout(), compute::readSmoothedGuides(ctx, buffers, vk::BufferUse::ComputeRead),
          compute::readRenderStrands(ctx, buffers, vk::BufferUse::ComputeWrite)};
}

HairAsset makeTestAsset(std::uint32_t guideCount, std::uint32_t particles, std::uint32_t perTriangle) {
  HairAsset asset;
  asset.name = "test fan";
  asset.guides.particlesPerGuide = particles;
  for (std::uint32_t g = 0; g < guideCount; ++g) {
    double angle = 6.283185307179586 * g / guideCount;
    glm::dvec3 root(0.1 * std::cos(angle), 0.0, 0.1 * std::sin(angle));
    glm::dvec3 out = glm::normalize(glm::dvec3(root.x, 0.3, root.z));
    glm::dvec3 p = root;
    double step = 0.02;
    for (std::uint32_t i = 0; i < particles; ++i) {
      asset.guides.positions.emplace_back(p);
      // Segments grow tip-ward and bend toward -Y with a twist: non-uniform, curved guides.
      glm::dvec3 dir = glm::normalize(out + glm::dvec3(0.3 * std::sin(i + g), -0.6 * i, 0.3 * std::cos(2.0 * i)));
      p += dir * step;
      step *= 1.35;
    }
  }
  std::vector<glm::vec3> roots = asset.guides.roots();
  std::vector<glm::uvec3> triangles;
  for (std::uint32_t g = 1; g + 1 < guideCount; ++g) triangles.emplace_back(0u, g, g + 1);
  DensityOptions density;
  density.mode = DensityOptions::Mode::PerTriangle;
  density.strandsPerTriangle = perTriangle;
  asset.topology = buildInterpolationTopology(roots, triangles, density);
  return asset;
}
}  // namespace hp::test
