#include "tests/compute/sim_reference.h"

#include <cmath>

#include "engine/core/error.h"
#include "shaders/shared/sdf.h"

namespace hp::test {
namespace {
constexpr double kTwoPi = 6.28318530718;

double gustPhase(std::uint32_t guide) {  // the shader's hash, bit for bit
  std::uint32_t h = guide * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  return double(float((h >> 22u) ^ h) * float(kTwoPi / 4294967296.0));
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// The shader's rotationBetween and keepLocalShape.
glm::dmat3 rotationBetween(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 v = glm::cross(a, b);
  const double c = glm::dot(a, b);
  if (c < -0.9999) return glm::dmat3(1.0);
  const glm::dmat3 vx(0.0, v.z, -v.y, -v.z, 0.0, v.x, v.y, -v.x, 0.0);
  return glm::dmat3(1.0) + vx + vx * vx / (1.0 + c);
}

void keepLocalShape(glm::dvec3* x, const glm::dvec4* rest, std::uint32_t n, const glm::dmat4& root, double k) {
  glm::dmat3 carried(root);
  for (std::uint32_t i = 1; i < n; ++i) {
    const glm::dvec3 expected = carried * (glm::dvec3(rest[i]) - glm::dvec3(rest[i - 1]));
    const glm::dvec3 delta = k * (x[i - 1] + expected - x[i]);
    if (i == 1) {
      x[i] += delta;
    } else {
      x[i - 1] -= 0.5 * delta;
      x[i] += 0.5 * delta;
    }
    const glm::dvec3 now = x[i] - x[i - 1];
    const double le = glm::length(expected), ln = glm::length(now);
    if (le > 1e-12 && ln > 1e-12) carried = rotationBetween(expected / le, now / ln) * carried;
  }
}

// The shader's resolvePearl: the surface point at rest length from the parent nearest to p, else radial.
glm::dvec3 resolvePearl(const glm::dvec3& p, const glm::dvec3& parent, double restLength, const glm::dvec3& center,
                        double reach) {
  glm::dvec3 fromCenter = p - center;
  double dist = glm::length(fromCenter);
  glm::dvec3 radial = center + (dist > 1e-12 ? fromCenter / dist : glm::dvec3(0, 1, 0)) * reach;
  glm::dvec3 axis = parent - center;
  double d = glm::length(axis);
  if (d < 1e-12 || d + reach < restLength || std::abs(d - reach) > restLength) return radial;
  axis /= d;
  double along = (d * d + reach * reach - restLength * restLength) / (2.0 * d);
  double ringRadius = std::sqrt(std::max(reach * reach - along * along, 0.0));
  glm::dvec3 inPlane = fromCenter - glm::dot(fromCenter, axis) * axis;
  double inPlaneLength = glm::length(inPlane);
  if (inPlaneLength < 1e-12) return radial;
  return center + along * axis + (ringRadius / inPlaneLength) * inPlane;
}
// sdf_collide.glsl in double: the trilinear sample (plus the distance to the box outside it) and the interpolant's
// own gradient from the same 8 nodes (central differences where it is flat: SDF_FLAT_GRADIENT), up to
// SDF_COLLISION_STEPS pushes to the clearance. Returns (gradient, value).
glm::dvec4 sampleGridGradient(const SdfGrid& g, const glm::dvec3& p) {
  const glm::dvec3 lo(g.origin), hi(g.upper());
  const glm::dvec3 clamped = glm::clamp(p, lo, hi), away = p - clamped;
  const double outside = glm::length(away);
  const glm::dvec3 f = (clamped - lo) / double(g.cell);
  const glm::uvec3 i0 = glm::min(glm::uvec3(f), g.dims - 2u);
  const glm::dvec3 t = f - glm::dvec3(i0);
  auto c = [&](std::uint32_t dx, std::uint32_t dy, std::uint32_t dz) { return double(g.at(i0.x + dx, i0.y + dy, i0.z + dz)); };
  const double x00 = glm::mix(c(0, 0, 0), c(1, 0, 0), t.x), x10 = glm::mix(c(0, 1, 0), c(1, 1, 0), t.x);
  const double x01 = glm::mix(c(0, 0, 1), c(1, 0, 1), t.x), x11 = glm::mix(c(0, 1, 1), c(1, 1, 1), t.x);
  const double value = glm::mix(glm::mix(x00, x10, t.y), glm::mix(x01, x11, t.y), t.z) + outside;
  glm::dvec3 d(
      glm::mix(glm::mix(c(1, 0, 0) - c(0, 0, 0), c(1, 1, 0) - c(0, 1, 0), t.y),
               glm::mix(c(1, 0, 1) - c(0, 0, 1), c(1, 1, 1) - c(0, 1, 1), t.y), t.z),
      glm::mix(glm::mix(c(0, 1, 0) - c(0, 0, 0), c(1, 1, 0) - c(1, 0, 0), t.x),
               glm::mix(c(0, 1, 1) - c(0, 0, 1), c(1, 1, 1) - c(1, 0, 1), t.x), t.z),
      glm::mix(glm::mix(c(0, 0, 1) - c(0, 0, 0), c(1, 0, 1) - c(1, 0, 0), t.x),
               glm::mix(c(0, 1, 1) - c(0, 1, 0), c(1, 1, 1) - c(1, 1, 0), t.x), t.y));
  d /= double(g.cell);
  for (int k = 0; k < 3; ++k)
    if (away[k] != 0.0) d[k] = 0.0;
  if (outside > 0.0) d += away / outside;
  return {d, value};
}

// Central differences of the value at half a cell, where the interpolant is flat across its cell.
glm::dvec3 centralGradient(const SdfGrid& g, const glm::dvec3& p) {
  const double h = 0.5 * g.cell;
  auto value = [&](const glm::dvec3& d) { return sampleGridGradient(g, p + d).w - sampleGridGradient(g, p - d).w; };
  return glm::dvec3(value({h, 0, 0}), value({0, h, 0}), value({0, 0, h})) / (2.0 * h);
}

glm::dvec3 keepOutsideGrid(const SdfGrid& g, const glm::dvec3& p, const glm::dmat4& head, double clearance) {
  glm::dvec3 q = apply(glm::inverse(head), p);
  bool moved = false;
  for (std::uint32_t step = 0; step < gpu::SDF_COLLISION_STEPS; ++step) {
    const glm::dvec4 s = sampleGridGradient(g, q);
    const double depth = clearance - s.w;
    if (depth <= 0.0) break;
    const double flat = double(gpu::SDF_FLAT_GRADIENT);
    const glm::dvec3 grad = glm::dot(glm::dvec3(s), glm::dvec3(s)) < flat * flat ? centralGradient(g, q) : glm::dvec3(s);
    const double len = glm::length(grad);
    if (len < 1e-6) break;
    q += grad * (depth / len);
    moved = true;
  }
  return moved ? apply(head, q) : p;
}
}  // namespace

SimReference::SimReference(const SimulatePass& pass, const SimulationParams& params, const glm::mat4& initialHead)
    : params_(params), n_(pass.particlesPerGuide()), colliders_(pass.colliders()), sdf_(pass.sdf()) {
  if (params.gridActs()) throw Error("SimReference: the CPU reference has no hair grid; pass withoutGrid(params)");
  for (const auto& r : pass.rest()) {
    rest_.push_back(glm::dvec4(r));
    x_.push_back(apply(glm::dmat4(initialHead), glm::dvec3(r)));
  }
  xPrev_ = x_;
}

void SimReference::step(const HeadMotion& motion) {
  for (std::size_t base = 0, g = 0; base < x_.size(); base += n_, ++g)
    simulateGuide(base, motion, static_cast<std::uint32_t>(g));
}

void SimReference::simulateGuide(std::size_t base, const HeadMotion& motion, std::uint32_t guide) {
  glm::dvec3* x = &x_[base];
  glm::dvec3* xp = &xPrev_[base];
  const glm::dvec4* rest = &rest_[base];
  const glm::dmat4 from(motion.from), to(motion.to);
  if (motion.teleport) {
    glm::dmat4 carry = to * glm::inverse(from);
    for (std::uint32_t i = 0; i < n_; ++i) {
      x[i] = apply(carry, x[i]);
      xp[i] = apply(carry, xp[i]);
    }
  }
  const double h = params_.dt / params_.substeps;
  const glm::dvec3 windDir = glm::length(params_.windDirection) > 0 ? glm::normalize(params_.windDirection) : glm::dvec3(0);
  for (std::uint32_t s = 0; s < params_.substeps; ++s) {
    double t = double(s + 1) / params_.substeps;
    glm::dmat4 head = motion.teleport ? to : from * (1.0 - t) + to * t;
    double gust = 1.0 + params_.windGust * std::sin(kTwoPi * params_.windGustFrequency * (motion.time + h * (s + 1)) + gustPhase(guide));
    glm::dvec3 accel = params_.gravity + windDir * params_.windStrength * gust;
    // Verlet with the root pinned.
    x[0] = apply(head, glm::dvec3(rest[0]));
    xp[0] = x[0];
    for (std::uint32_t i = 1; i < n_; ++i) {
      glm::dvec3 v = (x[i] - xp[i]) * (1.0 - params_.damping);
      double speed = glm::length(v), maxStep = params_.maxSpeed * h;
      if (speed > maxStep) v *= maxStep / speed;
      xp[i] = x[i];
      x[i] += v + accel * (h * h);
    }
    double k = params_.stiffness;
    for (std::uint32_t i = 1; i < n_ && k > 0.0; ++i, k *= params_.stiffnessFalloff)
      x[i] += k * (apply(head, glm::dvec3(rest[i])) - x[i]);
    for (std::uint32_t it = 0; it < params_.iterations; ++it) {
      if (params_.localStiffness > 0.0) keepLocalShape(x, rest, n_, head, params_.localStiffness);
      for (std::uint32_t i = 1; i < n_; ++i) {
        glm::dvec3 d = x[i] - x[i - 1];
        double len = glm::length(d);
        if (len < 1e-12) continue;
        glm::dvec3 corr = d * ((len - rest[i].w) / len);
        if (i == 1 || it + 1 == params_.iterations) {
          x[i] -= corr;
        } else {
          x[i - 1] += 0.5 * corr;
          x[i] -= 0.5 * corr;
        }
      }
      bool moved = true;
      for (std::uint32_t pass = 0; pass < gpu::SIM_COLLISION_PASSES && moved; ++pass) {
        moved = false;
        for (const auto& c : colliders_) {
          glm::dvec3 center = apply(head, glm::dvec3(c.center));
          double reach = double(c.radius) + params_.pearlRadius;
          for (std::uint32_t i = 1; i < n_; ++i) {
            if (glm::length(x[i] - center) >= reach) continue;
            x[i] = resolvePearl(x[i], x[i - 1], rest[i].w, center, reach);
            moved = true;
          }
        }
      }
      if (sdf_)
        for (std::uint32_t i = 1; i < n_; ++i) x[i] = keepOutsideGrid(*sdf_, x[i], head, params_.pearlRadius);
    }
  }
}
}  // namespace hp::test
