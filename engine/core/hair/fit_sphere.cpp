#include "engine/core/hair/fit_sphere.h"

#include <array>
#include <cmath>
#include <utility>

#include "engine/core/error.h"

namespace hp {
namespace {
using Mat4 = std::array<std::array<double, 5>, 4>;  // augmented [A | b]

// Gaussian elimination with partial pivoting; false if the system is (numerically) singular.
bool solve4(Mat4 m, glm::dvec4& x) {
  double scale = 0.0;
  for (auto& row : m)
    for (int c = 0; c < 4; ++c) scale = std::max(scale, std::abs(row[c]));
  for (int col = 0; col < 4; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 4; ++r)
      if (std::abs(m[r][col]) > std::abs(m[pivot][col])) pivot = r;
    if (std::abs(m[pivot][col]) <= 1e-10 * scale) return false;
    std::swap(m[col], m[pivot]);
    for (int r = 0; r < 4; ++r) {
      if (r == col) continue;
      double f = m[r][col] / m[col][col];
      for (int c = col; c < 5; ++c) m[r][c] -= f * m[col][c];
    }
  }
  for (int i = 0; i < 4; ++i) x[i] = m[i][4] / m[i][i];
  return true;
}

SphereFit standIn(const glm::dvec3& centroid, double extent) {
  double e = extent > 0.0 ? extent : 1.0;
  SphereFit fit;
  fit.sphere = {glm::vec3(centroid - glm::dvec3(0.0, e, 0.0)), static_cast<float>(e)};
  return fit;
}
}  // namespace

SphereFit fitSphere(std::span<const glm::vec3> points) {
  if (points.empty()) throw Error("sphere fit: no points");
  glm::dvec3 centroid(0.0);
  for (const auto& p : points) centroid += glm::dvec3(p);
  centroid /= double(points.size());
  double extent = 0.0;
  for (const auto& p : points) extent = std::max(extent, glm::length(glm::dvec3(p) - centroid));
  if (points.size() < 4 || extent <= 0.0) return standIn(centroid, extent);
  // Normal equations of rows [x y z 1] . (2c, k) = |p|^2 in units of `extent` around the centroid.
  Mat4 m{};
  for (const auto& p : points) {
    glm::dvec3 q = (glm::dvec3(p) - centroid) / extent;
    double row[4] = {q.x, q.y, q.z, 1.0}, rhs = glm::dot(q, q);
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) m[r][c] += row[r] * row[c];
      m[r][4] += row[r] * rhs;
    }
  }
  glm::dvec4 x;
  if (!solve4(m, x)) return standIn(centroid, extent);
  glm::dvec3 c(x.x / 2, x.y / 2, x.z / 2);
  double r2 = x.w + glm::dot(c, c);
  if (!(r2 > 0.0) || std::sqrt(r2) > 100.0 || !std::isfinite(r2)) return standIn(centroid, extent);
  SphereFit fit;
  fit.fitted = true;
  fit.sphere = {glm::vec3(centroid + c * extent), static_cast<float>(std::sqrt(r2) * extent)};
  double err = 0.0;
  for (const auto& p : points) {
    double d = glm::length(glm::dvec3(p) - glm::dvec3(fit.sphere.center)) - fit.sphere.radius;
    err += d * d;
  }
  fit.rmsError = static_cast<float>(std::sqrt(err / double(points.size())));
  return fit;
}
}  // namespace hp
