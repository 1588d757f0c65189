#include "engine/core/hair/sdf_program.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/sdf_primitives.h"

namespace hp::sdf {
namespace {
constexpr std::size_t kMaxDepth = 16;  // values on the evaluation stack at once

bool isLeaf(OpKind k) { return k < OpKind::Union; }

glm::vec3 mirrorPoint(const Op& op, const glm::vec3& p) { return op.mirrorX ? glm::vec3(std::abs(p.x), p.y, p.z) : p; }

float leafValue(const Op& op, const glm::vec3& p) {
  const glm::vec3 q = mirrorPoint(op, p);
  switch (op.kind) {
    case OpKind::Sphere: return sphere(q, op.a, op.ra);
    case OpKind::Ellipsoid: return ellipsoid(q, op.a, op.b);
    case OpKind::TaperedCapsule: return taperedCapsule(q, op.a, op.b, op.ra, op.rb);
    default: return op.ra - q.y;  // BelowPlaneY
  }
}

float blendValue(const Op& op, float a, float b) {
  switch (op.kind) {
    case OpKind::Union: return smoothUnion(a, b, op.k);
    case OpKind::Subtract: return smoothSubtract(a, b, op.k);
    default: return std::max(a, b);  // Max
  }
}

// ---- Bounds over a box (interval arithmetic; valid for every point of the box) ----
struct Box {
  glm::vec3 lo, hi;
};

Box mirrorBox(const Op& op, Box b) {
  if (!op.mirrorX) return b;
  if (b.lo.x >= 0.0f) return b;
  if (b.hi.x <= 0.0f) return {{-b.hi.x, b.lo.y, b.lo.z}, {-b.lo.x, b.hi.y, b.hi.z}};
  return {{0.0f, b.lo.y, b.lo.z}, {std::max(-b.lo.x, b.hi.x), b.hi.y, b.hi.z}};
}

// Smallest and largest length of a vector in the box [lo, hi].
Interval normRange(const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 nearest = glm::max(glm::max(lo, -hi), glm::vec3(0.0f));
  const glm::vec3 farthest = glm::max(glm::abs(lo), glm::abs(hi));
  return {glm::length(nearest), glm::length(farthest)};
}

// The ellipsoid estimate k0 (k0 - 1) / k1 is (k0 - 1) m with m = k0 / k1 in [min r, max r]
// (k1 = |q / r^2| lies between k0 / max r and k0 / min r).
Interval ellipsoidBounds(const Op& op, const Box& b) {
  const glm::vec3 r = op.b;
  const Interval k0 = normRange((b.lo - op.a) / r, (b.hi - op.a) / r);
  const Interval k1 = normRange((b.lo - op.a) / (r * r), (b.hi - op.a) / (r * r));
  const float rMin = std::min(r.x, std::min(r.y, r.z)), rMax = std::max(r.x, std::max(r.y, r.z));
  const float mLo = k1.hi > 0.0f ? std::clamp(k0.lo / k1.hi, rMin, rMax) : rMin;
  const float mHi = k1.lo > 0.0f ? std::clamp(k0.hi / k1.lo, mLo, rMax) : rMax;
  const float xLo = k0.lo - 1.0f, xHi = k0.hi - 1.0f;
  return {xLo >= 0.0f ? xLo * mLo : xLo * mHi, xHi >= 0.0f ? xHi * mHi : xHi * mLo};
}

// A capsule's distance is 1-Lipschitz up to its taper: bound it from the box's center.
Interval capsuleBounds(const Op& op, const Box& b) {
  const glm::vec3 center = 0.5f * (b.lo + b.hi);
  const float reach = 0.5f * glm::length(b.hi - b.lo);
  const float axis = taperedCapsule(center, op.a, op.b, 0.0f, 0.0f);
  const float taper = std::abs(op.rb - op.ra) / std::max(glm::length(op.b - op.a), 1e-12f);
  return {axis - reach - std::max(op.ra, op.rb), axis + reach * (1.0f + taper) - std::min(op.ra, op.rb)};
}

Interval leafBounds(const Op& op, const Box& box) {
  const Box b = mirrorBox(op, box);
  switch (op.kind) {
    case OpKind::Sphere: {
      const Interval d = normRange(b.lo - op.a, b.hi - op.a);
      return {d.lo - op.ra, d.hi - op.ra};
    }
    case OpKind::Ellipsoid: return ellipsoidBounds(op, b);
    case OpKind::TaperedCapsule: return capsuleBounds(op, b);
    default: return {op.ra - b.hi.y, op.ra - b.lo.y};  // BelowPlaneY
  }
}

// Slack for float rounding in the per-point evaluation (far below any blend radius).
float slack(const Interval& a, const Interval& b) {
  return 1e-6f + 1e-5f * (std::abs(a.lo) + std::abs(a.hi) + std::abs(b.lo) + std::abs(b.hi));
}

enum class Keep { Both, A, B };

// Which operands a blend needs over the box: dropping one must leave the exact per-point value.
// Union: min(a, b) with no blend when |a - b| >= k. Subtract: -union(-a, b) is a when b >= k - a.
// Max: a when a >= b (std::max returns its first argument on ties), b when b > a.
Keep needed(const Op& op, const Interval& a, const Interval& b) {
  const float e = slack(a, b);
  switch (op.kind) {
    case OpKind::Union:
      if (b.lo >= a.hi + op.k + e) return Keep::A;
      if (a.lo >= b.hi + op.k + e) return Keep::B;
      return Keep::Both;
    case OpKind::Subtract: return b.lo >= -a.lo + op.k + e ? Keep::A : Keep::Both;
    default:
      if (a.lo >= b.hi + e) return Keep::A;
      if (b.lo > a.hi + e) return Keep::B;
      return Keep::Both;
  }
}

// Each blend is nondecreasing in a; Union and Max also in b, Subtract nonincreasing in b.
Interval blendBounds(const Op& op, const Interval& a, const Interval& b) {
  switch (op.kind) {
    case OpKind::Union: return {smoothUnion(a.lo, b.lo, op.k), smoothUnion(a.hi, b.hi, op.k)};
    case OpKind::Subtract: return {smoothSubtract(a.lo, b.hi, op.k), smoothSubtract(a.hi, b.lo, op.k)};
    default: return {std::max(a.lo, b.lo), std::max(a.hi, b.hi)};
  }
}
}  // namespace

Program& Program::sphere(const glm::vec3& c, float r, bool mirrorX) {
  ops_.push_back({OpKind::Sphere, mirrorX, c, {}, r, 0.0f, 0.0f});
  return *this;
}
Program& Program::ellipsoid(const glm::vec3& c, const glm::vec3& radii, bool mirrorX) {
  if (!(radii.x > 0.0f && radii.y > 0.0f && radii.z > 0.0f)) throw Error("distance program: ellipsoid radii must be positive");
  ops_.push_back({OpKind::Ellipsoid, mirrorX, c, radii, 0.0f, 0.0f, 0.0f});
  return *this;
}
Program& Program::capsule(const glm::vec3& a, const glm::vec3& b, float r, bool mirrorX) {
  return taperedCapsule(a, b, r, r, mirrorX);
}
Program& Program::taperedCapsule(const glm::vec3& a, const glm::vec3& b, float ra, float rb, bool mirrorX) {
  if (!(glm::length(b - a) > 0.0f)) throw Error("distance program: a capsule needs two distinct end points");
  ops_.push_back({OpKind::TaperedCapsule, mirrorX, a, b, ra, rb, 0.0f});
  return *this;
}
Program& Program::belowPlaneY(float y) {
  ops_.push_back({OpKind::BelowPlaneY, false, {}, {}, y, 0.0f, 0.0f});
  return *this;
}

namespace {
void appendBlend(std::vector<Op>& ops, OpKind kind, float k) {
  if (kind != OpKind::Max && !(k > 0.0f)) throw Error("distance program: a blend radius must be positive");
  std::size_t depth = 0;
  for (const Op& op : ops) depth = isLeaf(op.kind) ? depth + 1 : depth - 1;
  if (depth < 2) throw Error("distance program: a blend needs two values below it");
  if (depth > kMaxDepth) throw Error("distance program: more than 16 values pending");
  ops.push_back({kind, false, {}, {}, 0.0f, 0.0f, k});
}
}  // namespace

Program& Program::smoothUnion(float k) {
  appendBlend(ops_, OpKind::Union, k);
  return *this;
}
Program& Program::smoothSubtract(float k) {
  appendBlend(ops_, OpKind::Subtract, k);
  return *this;
}
Program& Program::max() {
  appendBlend(ops_, OpKind::Max, 0.0f);
  return *this;
}

std::size_t Program::leaves() const {
  return std::size_t(std::count_if(ops_.begin(), ops_.end(), [](const Op& op) { return isLeaf(op.kind); }));
}

float Program::operator()(const glm::vec3& p) const {
  std::array<float, kMaxDepth + 1> stack;
  std::size_t n = 0;
  for (const Op& op : ops_) {
    if (isLeaf(op.kind)) {
      stack[n++] = leafValue(op, p);
    } else {
      --n;
      stack[n - 1] = blendValue(op, stack[n - 1], stack[n]);
    }
  }
  return n == 1 ? stack[0] : 0.0f;  // n == 1 for every built program but the empty one
}

namespace {
constexpr std::size_t kBatch = 64;

// A batch of points as three arrays (x, |x| for mirrored leaves, y, z): the loops below are plain
// float arithmetic over arrays, which the compiler turns into SIMD (this file is built with
// -fno-math-errno -fno-trapping-math so sqrt and the selects vectorise). Each loop spells out the
// same operations in the same order as the scalar primitive of sdf_primitives.h (glm::length is
// sqrt((x*x + y*y) + z*z), glm::mix(a, b, t) is a*(1-t) + b*t), so the values are bit for bit those
// of operator().
struct SoaBatch {
  alignas(16) float x[kBatch], ax[kBatch], y[kBatch], z[kBatch];
};

inline float len3(float x, float y, float z) { return std::sqrt(x * x + y * y + z * z); }

void leafBatch(const Op& op, const SoaBatch& p, float* __restrict out, std::size_t n) {
  const float* __restrict px = op.mirrorX ? p.ax : p.x;
  const float* __restrict py = p.y;
  const float* __restrict pz = p.z;
  const glm::vec3 a = op.a, b = op.b;
  switch (op.kind) {
    case OpKind::Sphere:
      for (std::size_t i = 0; i < n; ++i) out[i] = len3(px[i] - a.x, py[i] - a.y, pz[i] - a.z) - op.ra;
      break;
    case OpKind::Ellipsoid: {
      const glm::vec3 rr = b * b;
      const float rMin = std::min(b.x, std::min(b.y, b.z));
      for (std::size_t i = 0; i < n; ++i) {
        const float qx = px[i] - a.x, qy = py[i] - a.y, qz = pz[i] - a.z;
        const float k0 = len3(qx / b.x, qy / b.y, qz / b.z), k1 = len3(qx / rr.x, qy / rr.y, qz / rr.z);
        out[i] = k1 < 1e-12f ? -rMin : k0 * (k0 - 1.0f) / k1;
      }
      break;
    }
    case OpKind::TaperedCapsule: {
      const glm::vec3 ab = b - a;
      const float abab = glm::dot(ab, ab);
      for (std::size_t i = 0; i < n; ++i) {
        const float dx = px[i] - a.x, dy = py[i] - a.y, dz = pz[i] - a.z;
        const float t = glm::clamp((dx * ab.x + dy * ab.y + dz * ab.z) / abab, 0.0f, 1.0f);
        const float ex = px[i] - (a.x + t * ab.x), ey = py[i] - (a.y + t * ab.y), ez = pz[i] - (a.z + t * ab.z);
        out[i] = len3(ex, ey, ez) - glm::mix(op.ra, op.rb, t);
      }
      break;
    }
    default:
      for (std::size_t i = 0; i < n; ++i) out[i] = op.ra - py[i];
      break;
  }
}

void blendBatch(const Op& op, float* __restrict a, const float* __restrict b, std::size_t n) {
  switch (op.kind) {
    case OpKind::Union:
      for (std::size_t i = 0; i < n; ++i) a[i] = smoothUnion(a[i], b[i], op.k);
      break;
    case OpKind::Subtract:
      for (std::size_t i = 0; i < n; ++i) a[i] = smoothSubtract(a[i], b[i], op.k);
      break;
    default:
      for (std::size_t i = 0; i < n; ++i) a[i] = std::max(a[i], b[i]);
      break;
  }
}
}  // namespace

void Program::evaluate(std::span<const glm::vec3> points, std::span<float> out) const {
  if (out.size() != points.size()) throw Error("distance program: one output per point");
  alignas(16) float stack[kMaxDepth + 1][kBatch];
  SoaBatch batch;
  for (std::size_t first = 0; first < points.size(); first += kBatch) {
    const std::size_t n = std::min(kBatch, points.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec3& p = points[first + i];
      batch.x[i] = p.x, batch.ax[i] = std::abs(p.x), batch.y[i] = p.y, batch.z[i] = p.z;
    }
    std::size_t depth = 0;
    for (const Op& op : ops_) {
      if (isLeaf(op.kind)) {
        leafBatch(op, batch, stack[depth++], n);
      } else {
        --depth;
        blendBatch(op, stack[depth - 1], stack[depth], n);
      }
    }
    for (std::size_t i = 0; i < n; ++i) out[first + i] = depth == 1 ? stack[0][i] : 0.0f;
  }
}

Program Program::specialise(const glm::vec3& lo, const glm::vec3& hi, Interval* bounds) const {
  struct Entry {
    Interval range;
    std::size_t start;  // first op of this value in `out`
  };
  std::array<Entry, kMaxDepth + 1> stack;
  std::size_t n = 0;
  Program out;
  std::vector<Op>& o = out.ops_;
  o.reserve(ops_.size());
  const Box box{lo, hi};
  for (const Op& op : ops_) {
    if (isLeaf(op.kind)) {
      stack[n++] = {leafBounds(op, box), o.size()};
      o.push_back(op);
      continue;
    }
    const Entry b = stack[--n], a = stack[n - 1];
    switch (needed(op, a.range, b.range)) {
      case Keep::A: o.resize(b.start); break;
      case Keep::B:
        o.erase(o.begin() + std::ptrdiff_t(a.start), o.begin() + std::ptrdiff_t(b.start));
        stack[n - 1].range = b.range;
        break;
      case Keep::Both:
        o.push_back(op);
        stack[n - 1].range = blendBounds(op, a.range, b.range);
        break;
    }
  }
  if (bounds) *bounds = n == 1 ? stack[0].range : Interval{};
  return out;
}
}  // namespace hp::sdf
