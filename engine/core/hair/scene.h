#pragma once
// Contract: a scene as plain structs (the tools read it from a JSON scene file: samples/tools/host/
// scene_file.h; schema in engine/core/hair/README.md). Every field has a default, so a default Scene is the
// demo scene: the default head, lit and framed. buildSceneAsset turns a scene into the HairAsset the GPU
// side consumes (the public loadAsset builds one from its AssetSource).
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "engine/core/shading/light_limits.h"
#include "engine/core/hair/groom.h"
#include "engine/core/hair/collider.h"
#include "engine/core/hair/guide_growth.h"
#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/model_transform.h"
#include "engine/core/hair/sim_params.h"
#include "engine/core/hair/strand_topology.h"
#include "engine/core/shading/material.h"

namespace hp {
struct ModelSpec {
  enum class Kind { Default, Hair, Tfx, Obj };
  Kind kind = Kind::Default;
  std::filesystem::path path;   // absolute, or relative to the working directory
  ModelTransform transform;     // for .hair and .obj models
  bool keepStrands = false;     // .hair/.tfx: keep the strands' own points instead of resampling
};
// The model kind a file's extension names (.hair, .tfx, .obj, in any case); none for another extension.
std::optional<ModelSpec::Kind> modelKindOf(const std::filesystem::path& path);

// One light. `direction` always points from the lit hair toward the light: for a directional light
// that is all there is; for a spot it is minus the spot's axis (the spot shines along -direction from
// `position`); a point light shines from `position` in every direction (direction unused, but kept a unit
// vector). makeSpot aims a spot from a position at a target; makePoint places a point light.
struct LightSpec {
  enum class Type { Directional, Spot, Point };
  Type type = Type::Directional;
  glm::vec3 direction = glm::normalize(glm::vec3(0.5f, 0.8f, 0.6f));  // unit, from the hair toward the light
  glm::vec3 color{1.0f};  // linear RGB radiance colour
  float intensity = 3.0f;  // intensity x the largest colour component at most kMaxLightRadiance
  glm::vec3 position{0.0f};  // spot: world position
  float coneDeg = 30.0f;     // spot: cone half-angle in degrees, (0, 80]; the last 20% of it fades out
  float range = 0.0f;        // spot, point: inverse-square falloff (range / distance)^2 normalised at this
                             // distance (scene units); 0 = no distance falloff
  bool shadows = true;       // casts hair shadows while the Renderer has a shadow slot left for it

  static LightSpec makeSpot(const glm::vec3& position, const glm::vec3& target, float coneDeg);
  static LightSpec makePoint(const glm::vec3& position, float range = 0.0f);
  void validate() const;  // throws hp::Error naming the field
};

// A frame's lights: at most kMaxSceneLights (gpu::RENDER_MAX_LIGHTS, what the Renderer takes), none is
// allowed (only the ambient sky then). Throws hp::Error naming the bad light by index:
// "lights[2]: spot coneDeg must be in (0, 80], got 90".
inline constexpr std::size_t kMaxSceneLights = 8;
void validateLights(std::span<const LightSpec> lights);
// The shadow slots a Renderer drawing `lights` needs (RendererSettings::shadowedLights): the lights that
// ask for shadows (LightSpec::shadows), clamped to [1, gpu::OPACITY_MAX_LIGHTS] (the settings' range).
std::uint32_t shadowSlotsFor(std::span<const LightSpec> lights);
// The lower-case name of a light type ("directional", "spot", "point"), as the scene file and CLI spell it.
const char* lightTypeName(LightSpec::Type type);

struct CameraSpec {
  float orbitDeg = 30.0f;       // around +Y, 0 looks at the face from +Z
  float elevationDeg = 10.0f;   // above the horizon
  float distance = 0.9f;        // from target (scene units)
  float fovDeg = 35.0f;         // vertical field of view
  glm::vec3 target{0.0f, -0.08f, 0.0f};
};

// How the hair is drawn for the camera: the compute rasterizer (analytic coverage, front-to-back
// transparency; compute/raster/strand_raster_pass.h) or graphics ribbons (MSAA sample masks). Auto resolves
// per device type to the path measured faster (resolveRasterMode in compute/renderer/renderer_settings.h).
enum class RasterMode { Auto, Compute, Graphics };
RasterMode parseRasterMode(const std::string& text);  // "auto", "compute", "graphics"; else hp::Error
const char* rasterModeName(RasterMode mode);

struct RenderSpec {
  std::uint32_t width = 1280;
  std::uint32_t height = 720;
  std::uint32_t msaa = 4;  // 1, 2, 4 or 8: the samples of the head (both paths) and of the graphics path's hair
  RasterMode raster = RasterMode::Auto;
};

// A closed OBJ mesh the hair is kept outside of, through a distance grid built at load time.
struct MeshColliderSpec {
  std::filesystem::path path;
  float cell = 0.0f;  // grid spacing (scene units); 0: 1/64 of the mesh's longest side
};

// A character mesh (mesh_file.h: OBJ, PLY, glTF, .tfxmesh) in the model's units and axes (the model's
// transform applies to it): drawn as the head, collided with through a distance grid built at load time,
// and the surface the guides' roots bind to.
struct CharacterMeshSpec {
  std::filesystem::path path;
  float cell = 0.0f;  // distance grid spacing (scene units); 0: 1/128 of the mesh's longest side
};

struct Scene {
  std::string source = "<defaults>";  // where the scene came from, for messages
  ModelSpec model;
  GrowthOptions growth;  // defaults to defaultHeadGrowth()
  DensityOptions density{DensityOptions::Mode::Auto};  // none given: a model with many strands draws its own
  // Present: replaces the model's colliders (the default head's field included) with these spheres
  // and one distance grid built from colliderMeshes (if any). Absent: the model's own.
  std::optional<std::vector<SphereCollider>> colliders;
  std::vector<MeshColliderSpec> colliderMeshes;
  std::optional<CharacterMeshSpec> mesh;  // needs a model file (not the default head)
  HairMaterial material;
  std::vector<LightSpec> lights{LightSpec{}};  // validateLights; default: the one sun
  CameraSpec camera;
  RenderSpec render;
  SimulationParams simulation;
  GroomSettings groom = recommendedGroom();  // clumps, a wave and frizz at interpolation
  // Set when a model is loaded without a scene: what was guessed (units, up axis; empty: nothing)
  // and whether the camera should be framed on the hair once it is built.
  std::string guessed;
  bool fitCamera = false;

  Scene();
};

HairAsset buildSceneAsset(const Scene& scene);
}  // namespace hp
