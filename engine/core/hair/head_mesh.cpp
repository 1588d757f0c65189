#include "engine/core/hair/head_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/parallel_for.h"
#include "engine/core/number_text.h"

namespace hp {
HeadMesh makeEllipsoidMesh(const glm::vec3& center, const glm::vec3& radii, std::uint32_t slices,
                           std::uint32_t stacks) {
  HeadMesh m;
  const float pi = 3.14159265358979f;
  for (std::uint32_t i = 0; i <= stacks; ++i) {
    float theta = pi * float(i) / float(stacks);  // 0 at +Y
    for (std::uint32_t j = 0; j <= slices; ++j) {
      float phi = 2.0f * pi * float(j) / float(slices);
      glm::vec3 unit(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(center + unit * radii);
      m.normals.push_back(glm::normalize(unit / radii));  // ellipsoid normal: gradient of |x/r|^2
    }
  }
  const std::uint32_t row = slices + 1;
  for (std::uint32_t i = 0; i < stacks; ++i)
    for (std::uint32_t j = 0; j < slices; ++j) {
      std::uint32_t a = i * row + j, b = a + row, c = b + 1, d = a + 1;
      if (i != 0) m.indices.insert(m.indices.end(), {a, b, d});
      if (i + 1 != stacks) m.indices.insert(m.indices.end(), {d, b, c});
    }
  return m;
}

void appendMesh(HeadMesh& into, const HeadMesh& part) {
  auto base = static_cast<std::uint32_t>(into.positions.size());
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
  for (std::uint32_t i : part.indices) into.indices.push_back(base + i);
}
namespace {
// Nearest distance from p to any root except index `skip`.
float nearestRoot(const glm::vec3& p, std::span<const glm::vec3> roots, std::size_t skip) {
  float best = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < roots.size(); ++i)
    if (i != skip) best = std::min(best, glm::length(roots[i] - p));
  return best;
}

float meanRootSpacing(std::span<const glm::vec3> roots) {
  const std::size_t samples = std::min<std::size_t>(roots.size(), 256);
  const std::size_t stride = roots.size() / samples;
  double sum = 0.0;
  for (std::size_t k = 0; k < samples; ++k) sum += nearestRoot(roots[k * stride], roots, k * stride);
  return float(sum / double(samples));
}

// Roots bucketed in a grid of cubes (side >= reach) over their bounding box grown by `reach`: every
// root within `reach` of a point lies in the 27 cubes around the point's cube.
class RootBuckets {
 public:
  RootBuckets(std::span<const glm::vec3> roots, float reach) : roots_(roots) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const auto& r : roots) lo = glm::min(lo, r), hi = glm::max(hi, r);
    lo_ = lo - reach;
    const glm::vec3 extent = hi + reach - lo_;
    side_ = std::max(reach, std::max(extent.x, std::max(extent.y, extent.z)) / 128.0f);  // at most 129^3 cubes
    dims_ = glm::ivec3(extent / side_) + 1;
    std::vector<std::uint32_t> count(std::size_t(dims_.x) * dims_.y * dims_.z, 0);
    for (const auto& r : roots) ++count[index(cube(r))];
    start_.assign(count.size() + 1, 0);
    for (std::size_t i = 0; i < count.size(); ++i) start_[i + 1] = start_[i] + count[i];
    members_.resize(roots.size());
    for (std::uint32_t i = 0; i < roots.size(); ++i) members_[start_[index(cube(roots[i]))] + --count[index(cube(roots[i]))]] = i;
    // Most of a head (face, neck, shoulders) is far from every root: one flag per cube says whether
    // any of the 27 cubes around it holds a root, so those points skip the search.
    rootsAround_.assign(count.size(), 0);
    for (int z = 0; z < dims_.z; ++z)
      for (int y = 0; y < dims_.y; ++y)
        for (int x = 0; x < dims_.x; ++x) {
          const std::size_t i = index({x, y, z});
          if (start_[i] == start_[i + 1]) continue;
          for (int dz = std::max(z - 1, 0); dz <= std::min(z + 1, dims_.z - 1); ++dz)
            for (int dy = std::max(y - 1, 0); dy <= std::min(y + 1, dims_.y - 1); ++dy)
              for (int dx = std::max(x - 1, 0); dx <= std::min(x + 1, dims_.x - 1); ++dx) rootsAround_[index({dx, dy, dz})] = 1;
        }
  }

  // The distance to the nearest root if it is below `reach`, else `reach` or more.
  float nearest(const glm::vec3& p) const {
    float best = std::numeric_limits<float>::infinity();
    const glm::ivec3 c = cube(p);
    // Outside the grid (the roots' box grown by reach) or no root in the cubes around: none within reach.
    if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, dims_)) || !rootsAround_[index(c)])
      return best;
    for (int z = std::max(c.z - 1, 0); z <= std::min(c.z + 1, dims_.z - 1); ++z)
      for (int y = std::max(c.y - 1, 0); y <= std::min(c.y + 1, dims_.y - 1); ++y)
        for (int x = std::max(c.x - 1, 0); x <= std::min(c.x + 1, dims_.x - 1); ++x) {
          const std::size_t i = index({x, y, z});
          for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) best = std::min(best, glm::length(roots_[members_[k]] - p));
        }
    return best;
  }

 private:
  std::span<const glm::vec3> roots_;
  glm::vec3 lo_{0.0f};
  float side_ = 1.0f;
  glm::ivec3 dims_{1};
  std::vector<std::uint32_t> start_, members_;  // roots of cube i: members_[start_[i] .. start_[i + 1])
  std::vector<std::uint8_t> rootsAround_;        // per cube: 1 if it or a neighbour holds a root

  // Clamped one cube past the grid (monotone, so neighbours stay neighbours; those cubes are empty).
  glm::ivec3 cube(const glm::vec3& p) const {
    return glm::ivec3(glm::clamp(glm::floor((p - lo_) / side_), glm::vec3(-1.0f), glm::vec3(dims_)));
  }
  std::size_t index(const glm::ivec3& c) const { return (std::size_t(c.z) * dims_.y + c.y) * dims_.x + c.x; }
};
}  // namespace

void markScalp(HeadMesh& mesh, std::span<const glm::vec3> roots) {
  mesh.scalp.assign(mesh.positions.size(), 0.0f);
  if (roots.size() < 2) return;
  const float spacing = meanRootSpacing(roots);
  if (!(spacing > 0.0f) || !std::isfinite(spacing)) return;
  // Past three spacings the weight is 0: only roots closer than that matter, and a hash finds them.
  const RootBuckets buckets(roots, 3.0f * spacing);
  constexpr std::size_t kChunk = 4096;  // vertices per parallelFor index
  parallelFor((mesh.positions.size() + kChunk - 1) / kChunk, [&](std::size_t chunk) {
    const std::size_t end = std::min(mesh.positions.size(), (chunk + 1) * kChunk);
    for (std::size_t v = chunk * kChunk; v < end; ++v)
      mesh.scalp[v] = 1.0f - glm::smoothstep(spacing, 3.0f * spacing, buckets.nearest(mesh.positions[v]));
  }, 1);
}
void requireMeshShape(const HeadMesh& mesh, const std::string& where) {
  if (mesh.indices.size() % 3 != 0)
    throw Error(where + ": " + numberText(double(mesh.indices.size())) + " indices are not whole triangles");
  const std::string vertices = numberText(double(mesh.positions.size())) + " positions";
  if (mesh.normals.size() != mesh.positions.size())
    throw Error(where + ": " + numberText(double(mesh.normals.size())) + " normals for " + vertices);
  if (!mesh.scalp.empty() && mesh.scalp.size() != mesh.positions.size())
    throw Error(where + ": " + numberText(double(mesh.scalp.size())) + " scalp weights for " + vertices);
  for (const std::uint32_t i : mesh.indices)
    if (i >= mesh.positions.size()) throw Error(where + ": index " + numberText(i) + " past the " + vertices);
}
}  // namespace hp
