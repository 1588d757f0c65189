#pragma once
// Contract: the CPU reference of shaders/simulate.comp in double precision: the same algorithm, step
// for step (pin, Verlet with damping/clamp/wind, rest-pose pull, Gauss-Seidel lengths + collisions).
// Tests run it beside the device and compare. It has no hair grid: params must have it off (withoutGrid).
#include <glm/glm.hpp>

#include <vector>

#include "compute/strands/simulate_pass.h"

namespace hp::test {
// `p` with the hair grid off (volume and friction 0): the simulation the reference computes.
inline SimulationParams withoutGrid(SimulationParams p) {
  p.volume = 0.0;
  p.friction = 0.0;
  return p;
}

class SimReference {
 public:
  SimReference(const SimulatePass& pass, const SimulationParams& params, const glm::mat4& initialHead);
  void step(const HeadMotion& motion);
  const std::vector<glm::dvec3>& positions() const { return x_; }

 private:
  void simulateGuide(std::size_t base, const HeadMotion& motion, std::uint32_t guide);
  SimulationParams params_;
  std::uint32_t n_;
  std::vector<glm::dvec4> rest_;
  std::vector<SphereCollider> colliders_;
  std::shared_ptr<const SdfGrid> sdf_;
  std::vector<glm::dvec3> x_, xPrev_;
};
}  // namespace hp::test
