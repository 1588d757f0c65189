#include "samples/cli/output_paths.h"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"

namespace hp::cli {
namespace {
namespace fs = std::filesystem;

bool sameFile(const fs::path& a, const fs::path& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
  return fs::weakly_canonical(a, ec) == fs::weakly_canonical(b, ec);
}

std::string named(const CommandPath& p) { return p.option + " " + p.path.string(); }

void refuseInputs(const CommandPath& output, const std::vector<CommandPath>& inputs) {
  for (const auto& input : inputs)
    if (!input.path.empty() && sameFile(output.path, input.path))
      throw Error(named(output) + ": is the input given by " + input.option + "; refusing to overwrite it");
}

void makeWritableFolder(const CommandPath& output, const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw Error(named(output) + ": cannot create the folder " + folder.string() + " (" + ec.message() + ")");
  if (!fs::is_directory(folder, ec)) throw Error(named(output) + ": " + folder.string() + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw Error(named(output) + ": the folder " + folder.string() + " is not writable");
  // access() answers yes to root everywhere (/proc too): creating a file there is the real test, made
  // before any work so an unwritable output fails at once, not after the render.
  std::string probe = (folder / ".hairpipe-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    throw Error(named(output) + ": cannot create a file in " + folder.string() + " (" + std::strerror(errno) + ")");
  ::close(fd);
  ::unlink(probe.c_str());
}
}  // namespace

void prepareOutputFile(const CommandPath& output, const std::vector<CommandPath>& inputs) {
  if (output.path.empty()) throw Error(output.option + ": the output path is empty");
  refuseInputs(output, inputs);
  std::error_code ec;
  if (fs::is_directory(output.path, ec)) throw Error(named(output) + ": is a folder, expected a file name");
  // The file the write will replace (a link's target, whose folder must be writable), refused as the write
  // would refuse it: a device, a FIFO, a link that cannot be followed.
  fs::path target;
  try {
    target = atomicWriteDestination(output.path);
  } catch (const Error& e) {
    throw Error(output.option + " " + e.what());
  }
  makeWritableFolder(output, target.has_parent_path() ? target.parent_path() : fs::path("."));
}

void prepareOutputFolder(const CommandPath& output, const std::vector<CommandPath>& inputs,
                         const std::vector<std::string>& contents) {
  if (output.path.empty()) throw Error(output.option + ": the output folder is empty");
  refuseInputs(output, inputs);
  for (const std::string& name : contents) refuseInputs({output.option, output.path / name}, inputs);
  std::error_code ec;
  if (fs::exists(output.path, ec) && !fs::is_directory(output.path, ec))
    throw Error(named(output) + ": is a file, expected a folder");
  makeWritableFolder(output, output.path);
}

std::vector<CommandPath> sceneInputs(const SceneOptions& options, const Scene& scene) {
  std::vector<CommandPath> inputs;
  if (!options.scenePath.empty()) inputs.push_back({"--scene", options.scenePath});
  if (!scene.model.path.empty()) inputs.push_back({options.scenePath.empty() ? "--model" : "the scene's model", scene.model.path});
  for (const auto& m : scene.colliderMeshes) inputs.push_back({"the scene's collider mesh", m.path});
  return inputs;
}
}  // namespace hp::cli
