#include "samples/cli/scene_options.h"

#include <iostream>

#include "engine/error.h"

namespace hp::cli {
void addSceneOptions(CLI::App& cmd, SceneOptions& options) {
  auto* scene = cmd.add_option("--scene", options.scenePath, "Scene file (JSON; schema in engine/hair/README.md)");
  cmd.add_option("--model", options.model, "Model when no scene is given: default, FILE.hair or FILE.obj")
      ->excludes(scene);
  cmd.add_option("--device", options.device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd.add_flag("--validation", options.validation, "Run with the Khronos validation layer; fail on any message");
}

Scene loadScene(const SceneOptions& options) {
  if (!options.scenePath.empty()) return loadSceneFile(options.scenePath);
  Scene scene;
  if (options.model == "default") return scene;
  std::filesystem::path path(options.model);
  const std::string ext = path.extension().string();
  if (ext == ".hair")
    scene.model.kind = ModelSpec::Kind::Hair;
  else if (ext == ".obj")
    scene.model.kind = ModelSpec::Kind::Obj;
  else
    throw Error("--model " + options.model + ": expected 'default', a .hair file or an .obj file");
  scene.model.path = path;
  scene.source = options.model;
  return scene;
}

std::unique_ptr<vk::Context> createContext(const SceneOptions& options) {
  vk::ContextOptions ctxOptions;
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
