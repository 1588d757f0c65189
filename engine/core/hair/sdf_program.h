#pragma once
// Contract: a signed distance field written as a postfix program over the primitives and blends of
// sdf_primitives.h (an expression tree: leaves push a primitive's value, blends pop two and push one),
// so it can be (a) evaluated at a point and (b) specialised to a box. specialise() bounds every
// sub-expression over the box by interval arithmetic and drops each blend operand that cannot change
// the blend anywhere in the box (a smooth union whose other side is below it by more than its radius
// everywhere, a subtraction whose carving stays out of reach, a max whose other side always wins).
// The specialised program evaluates to bit-for-bit the same float as the whole one at every point of
// the box, only faster; the interval it returns bounds the field over the box. Deterministic.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp::sdf {
enum class OpKind : std::uint8_t { Sphere, Ellipsoid, TaperedCapsule, BelowPlaneY, Union, Subtract, Max };

struct Op {
  OpKind kind = OpKind::Sphere;
  bool mirrorX = false;  // leaves: evaluate at (|x|, y, z), so a left/right pair is one leaf
  glm::vec3 a{0.0f};     // center (sphere, ellipsoid), segment start (capsule)
  glm::vec3 b{0.0f};     // radii (ellipsoid), segment end (capsule)
  float ra = 0.0f;       // radius (sphere; capsule at a), the plane's y (BelowPlaneY: value ra - y)
  float rb = 0.0f;       // capsule radius at b
  float k = 0.0f;        // blend radius (Union, Subtract)
};

struct Interval {
  float lo = 0.0f, hi = 0.0f;
};

class Program {
 public:
  // Leaves and blends, appended in postfix order (a blend combines the two values below it: a, then b).
  Program& sphere(const glm::vec3& c, float r, bool mirrorX = false);
  Program& ellipsoid(const glm::vec3& c, const glm::vec3& radii, bool mirrorX = false);
  Program& capsule(const glm::vec3& a, const glm::vec3& b, float r, bool mirrorX = false);
  Program& taperedCapsule(const glm::vec3& a, const glm::vec3& b, float ra, float rb, bool mirrorX = false);
  Program& belowPlaneY(float y);  // positive below y: max() with it cuts a body flat at y
  Program& smoothUnion(float k);
  Program& smoothSubtract(float k);  // a with b carved out
  Program& max();

  float operator()(const glm::vec3& p) const;
  // out[i] = (*this)(points[i]) bit for bit, one op at a time over batches of points (no per-point
  // dispatch: several times faster for many points). out.size() == points.size().
  void evaluate(std::span<const glm::vec3> points, std::span<float> out) const;
  // The program restricted to the box [lo, hi]: same value at every point of the box. `bounds`
  // receives an interval holding every value the field takes in the box.
  Program specialise(const glm::vec3& lo, const glm::vec3& hi, Interval* bounds = nullptr) const;
  std::size_t size() const { return ops_.size(); }
  std::size_t leaves() const;

 private:
  std::vector<Op> ops_;
};
}  // namespace hp::sdf
