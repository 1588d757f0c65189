#pragma once
// Contract: one rendered frame as the files an offline renderer needs to reproduce it
// (`hairpipe render --export-frame DIR`, read back by `hairpipe reference --frame DIR`); the schema is
// docs/FRAME_EXPORT.md. Units are metres (scene units), Y up, world space (the head is placed).
//   DIR/strands.hair  the render strands as drawn: points, per-point thickness (fibre diameter) and
//                     per-point colour (the strand's colour, the same on each of its points)
//   DIR/head.obj      the opaque head: positions with per-vertex albedo ("v x y z r g b"), normals, triangles
//   DIR/frame.json    camera, lights, fibre material and model (with each strand's tilt offset and roughness scale), skin, ambient,
//                     background, exposure
// Every file is written atomically; readFrameExport validates everything and throws hp::Error naming
// the file and the problem. write then read reproduces every number exactly (floats printed round-trip).
#include <glm/glm.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/scene.h"
#include "engine/core/shading/environment_map.h"
#include "samples/tools/frame_capture.h"
#include "samples/tools/render_job.h"

namespace hp {
struct FrameCameraSpec {
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovYDeg = 35.0f;  // vertical
  std::uint32_t width = 0, height = 0;
};

struct ExportedFrame {
  HairFileData strands;  // thickness and colors arrays always present
  std::vector<glm::vec3> headPositions, headNormals, headAlbedo;
  std::vector<std::uint32_t> headIndices;
  FrameCameraSpec camera;
  std::vector<LightSpec> lights{LightSpec{}};  // [0, kMaxSceneLights] (default: the sun); a version 1 frame.json holds one
  HairMaterial material;
  std::string fibreModel = "marschner";  // reference/fibre.h names
  std::string lutMode = "float";         // what the real-time frame used
  glm::vec3 hairAlbedo{1.0f};            // exp(-2 sigma_a): strand colour = this x the strand's lightness scale
  glm::vec3 skinColor{1.0f};
  float wrap = 0.0f;                     // the real-time head's wrap term (the reference's skin is Lambert)
  float environment = 0.0f;              // uniform white sky radiance = the real-time ambient strength
  // The environment light, added to the uniform sky (environment.pfm beside frame.json, its intensity and
  // rotation in the JSON's "environment_map"); null: none.
  std::shared_ptr<const EnvironmentMap> environmentMap;
  glm::vec3 background{0.0f};            // radiance of camera rays that hit nothing
  float exposure = 1.0f;

  // Per strand: the cuticle tilt offset (radians) the real-time shading added to material.alphaR
  // (shaders/shared/strands.h strandTilt; zero in the LUT modes that ignore it); empty: none.
  std::vector<float> strandTilts;
  // Per strand: the scale the real-time shading applied to material.betaR (strands.h strandRoughness; none in
  // the LUT modes that ignore it); empty: none.
  std::vector<float> strandRoughness;

  // Per strand: the lightness scale the real-time shading multiplies the strand's radiance by.
  std::vector<float> strandColorScales() const;
  // The material strand s is shaded with: material, its alphaR plus the strand's tilt offset, its betaR times the
  // strand's roughness scale.
  HairMaterial strandMaterial(std::uint32_t s) const;
};

ExportedFrame makeExportedFrame(const RenderRequest& request, const HairAsset& asset, const FrameCapture& frame,
                                const std::string& fibreModel);
// The files an export folder holds: writeFrameExport's, then the real-time image and its hair coverage
// (`render --export-frame` writes those two beside them).
struct FrameExportFiles {
  static constexpr const char* strands = "strands.hair";
  static constexpr const char* head = "head.obj";
  static constexpr const char* json = "frame.json";
  static constexpr const char* environment = "environment.pfm";
  static constexpr const char* realtime = "realtime.pfm";
  static constexpr const char* realtimeHairAlpha = "realtime_hair_alpha.pfm";
  static constexpr const char* realtimeMotion = "realtime_motion.pfm";  // with --motion-vectors
  static std::vector<std::string> all() { return {strands, head, json, realtime, realtimeHairAlpha, realtimeMotion}; }
};
void writeFrameExport(const std::filesystem::path& dir, const ExportedFrame& frame);
ExportedFrame readFrameExport(const std::filesystem::path& dir);
}  // namespace hp
