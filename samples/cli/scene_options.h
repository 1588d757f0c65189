#pragma once
// Contract: the options every device command shares to say what to load and where to run it:
//   --scene FILE.json | --model default|FILE.hair|FILE.tfx|FILE.obj, --units m|cm|mm, --up y|z,
//   --device NAME|INDEX, --validation.
// loadScene() returns the scene file's content, or the default scene with the chosen model; a model
// without a scene gets its units and up axis guessed (--units/--up override) and a camera framed on
// it (Scene::guessed, Scene::fitCamera). --units/--up also override a scene's model keys.
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "engine/core/hair/scene.h"
#include "engine/vk/context.h"

namespace hp::cli {
struct SceneOptions {
  std::string scenePath;
  std::string model = "default";
  std::string units;  // empty: from the scene, or guessed
  std::string up;
  std::string mesh;  // a character mesh for the model (replaces the scene's)
  std::string device;
  bool validation = false;
};

void addSceneOptions(CLI::App& cmd, SceneOptions& options);
// What to load alone (--scene, --model, --units, --up, --mesh): for a command with a device option of its own.
void addModelOptions(CLI::App& cmd, SceneOptions& options);
Scene loadScene(const SceneOptions& options);
// `extensions` adds instance and device extensions (a windowed tool's surface and swapchain).
std::unique_ptr<vk::Context> createContext(const SceneOptions& options, const vk::ContextOptions& extensions = {});
// After a run with --validation: throws hp::Error listing the messages, if any.
void checkValidation(vk::Context& ctx);
}  // namespace hp::cli
