#include "samples/cli/scene_options.h"

#include <iostream>

#include "engine/core/error.h"
#include "engine/core/hair/mesh_file.h"
#include "samples/tools/host/model_guess.h"
#include "samples/tools/host/scene_file.h"

namespace hp::cli {
void addSceneOptions(CLI::App& cmd, SceneOptions& options) {
  addModelOptions(cmd, options);
  cmd.add_option("--device", options.device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd.add_flag("--validation", options.validation, "Run with the Khronos validation layer; fail on any message");
}

void addModelOptions(CLI::App& cmd, SceneOptions& options) {
  auto* scene = cmd.add_option("--scene", options.scenePath, "Scene file (JSON; schema in engine/core/hair/README.md)");
  cmd.add_option("--model", options.model, "Model when no scene is given: default, FILE.hair, FILE.tfx or FILE.obj")
      ->excludes(scene);
  cmd.add_option("--units", options.units, "Model units: m, cm or mm (default: the scene's, else guessed)");
  cmd.add_option("--up", options.up, "Model up axis: y or z (default: the scene's, else guessed)");
  cmd.add_option("--mesh", options.mesh,
                 "Character mesh for the model (.obj, .ply, .gltf, .glb or .tfxmesh, in the model's units): drawn, "
                 "collided with, roots bound to it");
}

namespace {
// --units/--up on top of whatever the scene says.
void applyOverrides(const SceneOptions& options, Scene& scene) {
  if (!options.units.empty()) scene.model.transform.scale = unitScale(options.units);
  if (!options.up.empty()) scene.model.transform.up = parseUpAxis(options.up);
}
}  // namespace

namespace {
Scene sceneOf(const SceneOptions& options);
}  // namespace

Scene loadScene(const SceneOptions& options) {
  if (!options.mesh.empty() && !meshKindOf(options.mesh))
    throw Error("--mesh " + options.mesh + ": expected an .obj, .ply, .gltf, .glb or .tfxmesh file");
  Scene scene = sceneOf(options);
  if (!options.mesh.empty()) scene.mesh = CharacterMeshSpec{options.mesh};
  return scene;
}

namespace {
Scene sceneOf(const SceneOptions& options) {
  if (!options.units.empty()) unitScale(options.units);  // refuse a bad value before any work
  if (!options.up.empty()) parseUpAxis(options.up);
  if (!options.scenePath.empty()) {
    Scene scene = loadSceneFile(options.scenePath);
    applyOverrides(options, scene);
    return scene;
  }
  Scene scene;
  if (options.model == "default") {
    if (!options.units.empty() || !options.up.empty()) throw Error("--units/--up apply to a --model file");
    return scene;
  }
  std::filesystem::path path(options.model);
  const std::string ext = path.extension().string();
  if (ext == ".hair")
    scene.model.kind = ModelSpec::Kind::Hair;
  else if (ext == ".tfx")
    scene.model.kind = ModelSpec::Kind::Tfx;
  else if (ext == ".obj")
    scene.model.kind = ModelSpec::Kind::Obj;
  else
    throw Error("--model " + options.model + ": expected 'default', a .hair, .tfx or .obj file");
  scene.model.path = path;
  scene.source = options.model;
  const ModelGuess guess = guessModelFileTransform(
      path, options.units.empty() ? std::nullopt : std::optional<std::string>(options.units),
      options.up.empty() ? std::nullopt : std::optional<UpAxis>(parseUpAxis(options.up)));
  scene.model.transform = guess.transform;
  scene.guessed = guess.reason;
  scene.fitCamera = true;
  return scene;
}
}  // namespace

std::unique_ptr<vk::Context> createContext(const SceneOptions& options, const vk::ContextOptions& extensions) {
  vk::ContextOptions ctxOptions = extensions;
  ctxOptions.device = options.device;
  ctxOptions.validation = options.validation;
  auto ctx = vk::Context::createHeadless(ctxOptions);
  ctx->validationLog().setEcho(true);
  return ctx;
}

void checkValidation(vk::Context& ctx) {
  if (ctx.validationEnabled() && ctx.validationLog().problemCount() > 0)
    throw Error(std::to_string(ctx.validationLog().problemCount()) + " Vulkan validation message(s) were reported");
}
}  // namespace hp::cli
