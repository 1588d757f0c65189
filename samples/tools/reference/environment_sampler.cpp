#include "samples/tools/reference/environment_sampler.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/luminance.h"

namespace hp::reference {
EnvironmentSampler::EnvironmentSampler(const EnvironmentMap& map) : map_(map) {
  const std::uint32_t w = map.width, h = map.height;
  std::vector<double> lum(std::size_t(w) * h);
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) lum[std::size_t(y) * w + x] = luminanceOf(map.texelRadiance(x, y));
  cdf_.resize(lum.size());
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      double peak = 0.0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::int64_t yy = std::clamp<std::int64_t>(std::int64_t(y) + dy, 0, h - 1);
          const std::int64_t xx = (std::int64_t(x) + dx + w) % w;
          peak = std::max(peak, lum[std::size_t(yy) * w + std::size_t(xx)]);
        }
      total_ += peak * map.texelSolidAngle(y);
      cdf_[std::size_t(y) * w + x] = total_;
    }
}

double EnvironmentSampler::texelPdf(std::size_t texel) const {
  const double before = texel > 0 ? cdf_[texel - 1] : 0.0;
  const auto y = std::uint32_t(texel / map_.width);
  return (cdf_[texel] - before) / total_ / map_.texelSolidAngle(y);
}

std::size_t EnvironmentSampler::texelOf(const glm::dvec3& dir) const {
  glm::dvec2 p = map_.imagePoint(dir);
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) p = glm::dvec2(0.0);  // not a direction: any texel, its pdf
  const auto x = std::uint32_t(std::clamp(std::floor(p.x * map_.width), 0.0, double(map_.width - 1)));
  const auto y = std::uint32_t(std::clamp(std::floor(p.y * map_.height), 0.0, double(map_.height - 1)));
  return std::size_t(y) * map_.width + x;
}

glm::dvec3 EnvironmentSampler::sample(Sampler& rng, double& pdf) const {
  const double target = rng.next() * total_;
  const std::size_t texel = std::min<std::size_t>(
      std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()), cdf_.size() - 1);
  const std::uint32_t x = std::uint32_t(texel % map_.width), y = std::uint32_t(texel / map_.width);
  // Uniform in solid angle inside the texel: cos(polar) uniform between its rows, azimuth uniform.
  const double zTop = std::cos(kPi * y / map_.height), zBottom = std::cos(kPi * (y + 1) / map_.height);
  const double z = zTop + rng.next() * (zBottom - zTop);
  const double u = (x + rng.next()) / map_.width, v = std::acos(std::clamp(z, -1.0, 1.0)) / kPi;
  pdf = texelPdf(texel);
  return map_.direction(u, v);
}

double EnvironmentSampler::pdf(const glm::dvec3& dir) const { return empty() ? 0.0 : texelPdf(texelOf(dir)); }
}  // namespace hp::reference
