#pragma once
// Contract: guide strands as one flat array, particlesPerGuide consecutive positions per guide, root
// first. particlesPerGuide is in [kMinParticlesPerGuide, kMaxParticlesPerGuide]; positions.size() is
// always a multiple of it. Rest lengths are not stored: the simulation takes them from the rest pose.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp {
inline constexpr std::uint32_t kDefaultParticlesPerGuide = 7;
inline constexpr std::uint32_t kMinParticlesPerGuide = 2;
inline constexpr std::uint32_t kMaxParticlesPerGuide = 64;

struct GuideSet {
  std::uint32_t particlesPerGuide = kDefaultParticlesPerGuide;
  std::vector<glm::vec3> positions;  // guideCount() * particlesPerGuide, root first

  std::uint32_t guideCount() const {
    return static_cast<std::uint32_t>(positions.size() / particlesPerGuide);
  }
  std::span<const glm::vec3> guide(std::uint32_t g) const {
    return {positions.data() + std::size_t(g) * particlesPerGuide, particlesPerGuide};
  }
  std::span<glm::vec3> guide(std::uint32_t g) {
    return {positions.data() + std::size_t(g) * particlesPerGuide, particlesPerGuide};
  }
  const glm::vec3& root(std::uint32_t g) const { return positions[std::size_t(g) * particlesPerGuide]; }
  std::vector<glm::vec3> roots() const;
};

// Throws hp::Error when particles is outside [kMinParticlesPerGuide, kMaxParticlesPerGuide].
void checkParticlesPerGuide(std::uint32_t particles, const char* what);
}  // namespace hp
