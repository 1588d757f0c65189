#include "tests/render/opacity_reference.h"

#include <algorithm>
#include <cmath>

#include "compute/shadows/bounds_pass.h"

namespace hp::test {
namespace {
void deposit(OpacityGrid& g, std::int64_t x, std::int64_t y, double s, double opacity) {
  const std::int64_t n = g.resolution;
  if (x < 0 || y < 0 || x >= n || y >= n) return;
  for (std::uint32_t i = 1; i <= gpu::OPACITY_SLICES; ++i)
    if (s <= i + double(gpu::OPACITY_SLICE_EPSILON))
      g.alpha[(std::size_t(i - 1) * n + y) * n + x] += opacity;
}

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}
}  // namespace

LightBox lightBounds(const std::vector<glm::vec4>& points, const glm::vec3& towardLight) {
  const glm::dmat3 rows(compute::lightBasisRows(towardLight));
  LightBox box;
  for (const glm::vec4& p : points) {
    const glm::dvec3 c = rows * glm::dvec3(p);  // (x, y, L.p)
    const glm::dvec3 l(c.x, c.y, -c.z);
    box.lo = glm::min(box.lo, l);
    box.hi = glm::max(box.hi, l);
  }
  return box;
}

LightBox spotBounds(const std::vector<glm::vec4>& points, const glm::vec3& position, const glm::vec3& towardLight) {
  const glm::dmat3 rows(compute::lightBasisRows(towardLight));
  LightBox box;
  for (const glm::vec4& p : points) {
    const glm::dvec3 c = rows * (glm::dvec3(p) - glm::dvec3(position));
    const double d = -c.z;
    if (!(d > compute::kSpotNearLimit)) continue;
    const glm::dvec3 l(c.x / d, c.y / d, d);
    box.lo = glm::min(box.lo, l);
    box.hi = glm::max(box.hi, l);
  }
  return box;
}

glm::dvec3 texelAndSlice(const gpu::LightSpace& light, std::uint32_t n, const glm::dvec3& world) {
  const glm::dvec4 clip = glm::dmat4(light.viewProj) * glm::dvec4(world, 1.0);
  return {(clip.x / clip.w * 0.5 + 0.5) * n, (0.5 - clip.y / clip.w * 0.5) * n, clip.z * gpu::OPACITY_SLICES};
}

void rasterizeSegments(OpacityGrid& g, const gpu::LightSpace& light, const std::vector<glm::dvec3>& a,
                       const std::vector<glm::dvec3>& b, double opacity) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    const glm::dvec3 p = texelAndSlice(light, g.resolution, a[k]), q = texelAndSlice(light, g.resolution, b[k]);
    const glm::dvec2 d(q.x - p.x, q.y - p.y);
    const double len = glm::length(d);
    if (len <= 0.0) continue;
    const glm::dvec2 dir = d / len;
    // Texel centres inside the 1-texel-wide rectangle along the segment (the strict-line rule).
    const auto x0 = std::int64_t(std::floor(std::min(p.x, q.x) - 1)), x1 = std::int64_t(std::ceil(std::max(p.x, q.x) + 1));
    const auto y0 = std::int64_t(std::floor(std::min(p.y, q.y) - 1)), y1 = std::int64_t(std::ceil(std::max(p.y, q.y) + 1));
    for (std::int64_t y = y0; y <= y1; ++y)
      for (std::int64_t x = x0; x <= x1; ++x) {
        const glm::dvec2 r(x + 0.5 - p.x, y + 0.5 - p.y);
        const double along = glm::dot(r, dir), across = dir.x * r.y - dir.y * r.x;
        if (along < 0.0 || along >= len || across < -0.5 || across >= 0.5) continue;
        deposit(g, x, y, p.z + (along / len) * (q.z - p.z), opacity);
      }
  }
}

void rasterizeTriangles(OpacityGrid& g, const gpu::LightSpace& light, const std::vector<glm::dvec3>& corners,
                        double opacity) {
  for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
    glm::dvec3 v[3];
    for (int i = 0; i < 3; ++i) v[i] = texelAndSlice(light, g.resolution, corners[k + i]);
    const glm::dvec2 a(v[0]), b(v[1]), c(v[2]);
    const double area = edge(a, b, c);
    if (area == 0.0) continue;
    const auto x0 = std::int64_t(std::floor(std::min({a.x, b.x, c.x}))), x1 = std::int64_t(std::ceil(std::max({a.x, b.x, c.x})));
    const auto y0 = std::int64_t(std::floor(std::min({a.y, b.y, c.y}))), y1 = std::int64_t(std::ceil(std::max({a.y, b.y, c.y})));
    for (std::int64_t y = std::max<std::int64_t>(y0, 0); y <= std::min<std::int64_t>(y1, g.resolution - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(x0, 0); x <= std::min<std::int64_t>(x1, g.resolution - 1); ++x) {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        const double w0 = edge(b, c, p) / area, w1 = edge(c, a, p) / area, w2 = edge(a, b, p) / area;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        deposit(g, x, y, w0 * v[0].z + w1 * v[1].z + w2 * v[2].z, opacity);
      }
  }
}

double lookupAlpha(const render::OpacityCapture& c, std::uint32_t x, std::uint32_t y, double s) {
  s = std::clamp(s, 0.0, double(gpu::OPACITY_SLICES));
  double alpha = 0.0;
  for (std::uint32_t i = 1; i <= gpu::OPACITY_SLICES; ++i)
    alpha += std::max(0.0, 1.0 - std::abs(s - i)) * c.at(i - 1, x, y);
  return alpha;
}
}  // namespace hp::test
