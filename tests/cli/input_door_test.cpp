// One bounded door for input bytes: every reader of a user's file, listed here, refuses a device file
// (/dev/zero), a FIFO and a directory by path, before reading (a FIFO would hang, /dev/zero grow memory
// without end). A new reader belongs in kReaders.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/gltf_mesh.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/ply_file.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "engine/core/hair/tfx_mesh_file.h"
#include "engine/core/hair/tfx_file.h"
#include "samples/tools/environment_file.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/host/scene_file.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/obj_albedo_mesh.h"
#include "samples/tools/png_file.h"
#include "tests/support/cli_runner.h"
#include "tests/support/refusal.h"

namespace {
struct Reader {
  const char* name;
  std::function<void(const std::filesystem::path&)> read;
};

// Each reader of a user-named file. A frame export is a folder: its frame.json is the file under test.
const std::vector<Reader> kReaders = {
    {".hair", [](const auto& p) { (void)hp::readHairFile(p); }},
    {".tfx", [](const auto& p) { (void)hp::readTfxFile(p); }},
    {"OBJ scalp", [](const auto& p) { (void)hp::loadObjScalp(p); }},
    {".tfxbone", [](const auto& p) { (void)hp::readTfxBoneFile(p); }},
    {"PLY mesh", [](const auto& p) { (void)hp::readPlyFile(p); }},
    {"glTF mesh", [](const auto& p) { (void)hp::readGltfFile(p); }},
    {".tfxmesh", [](const auto& p) { (void)hp::readTfxMeshFile(p); }},
    {"scene JSON", [](const auto& p) { (void)hp::loadSceneFile(p); }},
    {"PFM", [](const auto& p) { (void)hp::readPfm(p); }},
    {"environment .hdr", [](const auto& p) { (void)hp::readHdrEnvironment(p); }},
    {"PNG", [](const auto& p) { (void)hp::readPngRgba(p); }},
    {"frame export head.obj", [](const auto& p) { (void)hp::readAlbedoObj(p); }},
};

std::string refusal(const Reader& reader, const std::filesystem::path& path) {
  return hp::test::refusalOf([&] { reader.read(path); });
}
}  // namespace

TEST(InputDoor, EveryReaderRefusesDevicesFifosAndFoldersByPath) {
  const auto dir = hp::test::freshTempPath("hairpipe_input_door");
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path fifo = dir / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const Reader& reader : kReaders)
    for (const std::filesystem::path& path : {std::filesystem::path("/dev/zero"), fifo, dir}) {
      const std::string message = refusal(reader, path);
      EXPECT_NE(message.find(path.string() + ": cannot open (not a regular file"), std::string::npos)
          << reader.name << " on " << path << ": " << message;
    }
  // A frame export's frame.json and the BRDF tool's query table, through the command line.
  std::filesystem::create_directories(dir / "export");
  ASSERT_EQ(::mkfifo((dir / "export" / "frame.json").c_str(), 0600), 0);
  const auto out = dir / "out.pfm";
  hp::test::expectRefused({"reference", "--frame", (dir / "export").string(), "--out", out.string()},
                          {{{}, "frame.json: cannot open (not a regular file"}}, out);
  hp::test::expectRefused({"brdf", "--out", (dir / "out.csv").string()},
                          {{{"--in", "/dev/zero"}, "/dev/zero: cannot open (not a regular file"},
                           {{"--in", fifo.string()}, "pipe: cannot open (not a regular file"}},
                          dir / "out.csv");
  std::filesystem::remove_all(dir);
}
