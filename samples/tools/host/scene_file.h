#pragma once
// Contract: a scene file (JSON; schema in engine/core/hair/README.md) read into hp::Scene. loadSceneFile rejects
// syntax errors, unknown keys, wrong types and out-of-range values with hp::Error naming the file and the
// JSON pointer; paths in the scene are relative to the scene file's directory. A tool's format: the
// library takes its values through the public API.
#include <filesystem>
#include <string>

#include "engine/core/hair/scene.h"

namespace hp {
Scene loadSceneFile(const std::filesystem::path& path);
// `source` names the text in messages; relative model paths resolve against baseDir.
Scene parseScene(const std::string& jsonText, const std::string& source, const std::filesystem::path& baseDir);
}  // namespace hp
