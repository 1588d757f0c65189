#pragma once
// Contract: the output rule every command applies before it does any work. Each output file's folder
// is created if missing and must be writable; an output must not be one of the command's inputs (the
// same file, by identity or by normalised path), nor an existing folder; an output folder must not be
// an existing file, nor hold an input under a name the command writes there. Throws hp::Error naming the option and the path. The files themselves are then
// written atomically (engine/core/hair/atomic_write.h), so a failed run leaves no partial file.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/hair/scene.h"
#include "samples/cli/scene_options.h"

namespace hp::cli {
struct CommandPath {
  std::string option;  // "--out", "--scalp", "scene model", ...
  std::filesystem::path path;
};

void prepareOutputFile(const CommandPath& output, const std::vector<CommandPath>& inputs);
// `contents`: the names the command writes into the folder; none may be one of the inputs.
void prepareOutputFolder(const CommandPath& output, const std::vector<CommandPath>& inputs,
                         const std::vector<std::string>& contents = {});
// The files a scene command reads: the scene file (if any) and the model it names.
std::vector<CommandPath> sceneInputs(const SceneOptions& options, const Scene& scene);
}  // namespace hp::cli
