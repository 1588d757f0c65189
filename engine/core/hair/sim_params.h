#pragma once
// Contract: parameters of the guide simulation (docs/THEORY.md §2). Units are scene units (metres for
// the default head) and seconds. validate() throws hp::Error naming the first bad field: NaN/Inf,
// dt <= 0, iterations outside [1, 1000], negative radii, damping outside [0, 1], and so on.
#include <glm/glm.hpp>

#include <cstdint>

namespace hp {
struct SimulationParams {
  double dt = 1.0 / 60.0;                 // frame time step (s)
  std::uint32_t substeps = 2;             // Verlet substeps per frame
  std::uint32_t iterations = 8;           // length-constraint + collision iterations per substep
  glm::dvec3 gravity = {0.0, -9.81, 0.0}; // m/s^2, world space, at most 1e5 long
  double damping = 0.02;                  // fraction of velocity removed per substep, [0, 1]
  double pearlRadius = 0.002;             // r_p: sphere around every particle (scene units), [0, 1000]
  double stiffness = 0.05;                // shape stiffness toward the rest pose at the root, [0, 1]
  double stiffnessFalloff = 0.7;          // per-segment decay of the stiffness toward the tip, [0, 1]
  // Local shape (docs/THEORY.md §2.6): every constraint iteration, each segment moves this fraction of the way
  // to its rest-pose segment as seen from its parent segment as it lies now; keeps a strand's own bends
  // (waves, curls) under gravity and motion. [0, 0.9] (nearer 1 the corrections overshoot); 0: off.
  double localStiffness = 0.0;
  double maxSpeed = 10.0;                 // particle speed clamp (scene units / s), (0, 1e6]
  // Strand interaction through a density / velocity grid around the instance (docs/THEORY.md §2.7), built once a
  // frame from the guides' state at its start; the grid acts when volume or friction is above 0.
  // volume: how fast hair flows down the pressure gradient out of places denser than volumeTarget, in grid
  // cells a frame per unit of density excess over a cell, [0, 10] (per cell and frame so that its stability does not
  // depend on the resolution or the frame rate). volumeTarget: in units of the rest pose's mean density,
  // [0.01, 100]. friction: fraction of each particle's velocity pulled toward the grid's (the hair
  // around it) per substep, [0, 1]. gridResolution: cells along the grid's longest side, [4, 128].
  // Off by default (volume = friction = 0: exactly the simulation without it); volume 0.6, friction 0.1 are the
  // values chosen by looking at the default head (docs/THEORY.md §2.7).
  double volume = 0.0;
  double volumeTarget = 0.5;
  double friction = 0.0;
  std::uint32_t gridResolution = 32;
  glm::dvec3 windDirection = {1.0, 0.0, 0.0};
  double windStrength = 0.0;              // acceleration (scene units / s^2) along windDirection, [0, 1e5]
  double windGust = 0.0;                  // relative gust amplitude, [0, 1]
  double windGustFrequency = 0.5;         // Hz

  void validate() const;
  bool gridActs() const { return volume > 0.0 || friction > 0.0; }
};

// The hair grid's volume and friction chosen by looking at the default head (docs/THEORY.md §2.7).
inline constexpr double kRecommendedVolume = 0.6;
inline constexpr double kRecommendedFriction = 0.1;
// `p` with the hair grid on at those values.
inline SimulationParams withHairGrid(SimulationParams p) {
  p.volume = kRecommendedVolume;
  p.friction = kRecommendedFriction;
  return p;
}
}  // namespace hp
