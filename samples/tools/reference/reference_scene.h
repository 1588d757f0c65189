#pragma once
// Contract: the exported frame's geometry in Embree 3 for the path tracer: every render strand as a
// round linear curve through its points with radius = thickness / 2 (rounded joints, as one tube),
// and the head as an opaque triangle mesh. intersect() returns the nearest hit with what shading needs
// (fibre: tangent and strand; head: normals and albedo interpolated as the rasteriser does);
// occluded() answers a shadow ray. Hits where a ray leaves a tube (the tube's outward normal along the
// ray) are not hits: a ray that starts inside a tube (its own, or another strand's where tubes
// overlap, or a root inside the head) is not stopped by that tube, so every hit is a ray entering the
// union of tubes as drawn. Rays leave a fibre from its surface (fibreExitOrigin). Thread-safe after
// construction; throws hp::Error when Embree fails.
#include <glm/glm.hpp>

#include <embree3/rtcore.h>

#include <cstdint>
#include <vector>

#include "samples/tools/frame_export.h"

namespace hp::reference {
struct SceneHit {
  enum class Kind { None, Fibre, Head } kind = Kind::None;
  double t = 0.0;
  glm::dvec3 point{0.0};
  glm::dvec3 tangent{0.0};       // fibre: unit, root to tip
  std::uint32_t strand = 0;      // fibre
  double radius = 0.0;           // fibre: at the hit
  glm::dvec3 axisPoint{0.0};     // fibre: the hit projected onto the strand's axis
  glm::dvec3 normal{0.0};        // head: interpolated shading normal, unit
  glm::dvec3 geometricNormal{0.0};  // head: unit
  glm::dvec3 albedo{0.0};        // head
};

// Where a ray leaving fibre hit `h` toward unit `dir` starts: the point of the tube's surface that faces
// `dir` across the axis (at the hit's axis point). The far-field fibre scatters over its whole width;
// light arriving from `dir` (or leaving toward it) meets the fibre on that side, so the ray starts on the
// tube as drawn and not on its axis, which in dense hair lies inside other strands' tubes.
glm::dvec3 fibreExitOrigin(const SceneHit& h, const glm::dvec3& dir);

class ReferenceScene {
 public:
  explicit ReferenceScene(const ExportedFrame& frame);
  ~ReferenceScene();
  ReferenceScene(const ReferenceScene&) = delete;
  ReferenceScene& operator=(const ReferenceScene&) = delete;

  SceneHit intersect(const glm::dvec3& origin, const glm::dvec3& dir, float tnear) const;
  bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, float tnear, float tfar) const;
  float sceneScale() const { return scale_; }  // bounding box diagonal, for ray offsets
  // The axis point of a strand segment at curve parameter u (what the exit test of a hit measures from).
  glm::vec3 axisAt(std::uint32_t segment, float u) const;

 private:
  void addStrands(const HairFileData& strands);
  void addHead(const ExportedFrame& frame);
  SceneHit fibreHit(std::uint32_t segment, float u, const glm::dvec3& point) const;
  SceneHit headHit(std::uint32_t triangle, float u, float v, const glm::dvec3& ng) const;

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  unsigned curveGeom_ = 0, headGeom_ = 0;
  std::vector<glm::vec4> curvePoints_;          // xyz, radius
  std::vector<glm::vec3> curveTangents_;        // per point, central differences
  std::vector<std::uint32_t> segmentFirst_;     // per segment: its first point
  std::vector<std::uint32_t> segmentStrand_;    // per segment: its strand
  std::vector<glm::vec3> headPositions_, headNormals_, headAlbedo_;
  std::vector<std::uint32_t> headIndices_;
  float scale_ = 1.0f;
};
}  // namespace hp::reference
