// Hostile inputs the asset readers must refuse with a short hp::Error instead of crashing, hanging or
// exhausting memory: nesting, overflowing numbers, huge keys, device files, material libraries.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/input_file.h"
#include "engine/core/hair/tfx_file.h"
#include "samples/tools/host/json_reader.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
std::string sceneError(const std::string& json) {
  return test::errorOf([&] { parseScene(json, "scene.json", "/base"); });
}

std::string nested(int depth) { return std::string(depth, '[') + std::string(depth, ']'); }

const char* kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST(InputLimits, DeepNestingIsRefusedBeforeAnyRecursion) {
  // 200,000 levels overflowed the stack in a recursive copy before the limit existed.
  const std::string msg = sceneError("{\"model\": " + nested(200000) + "}");
  EXPECT_NE(msg.find("scene.json: invalid JSON: nested deeper than 32 levels"), std::string::npos) << msg;
  EXPECT_LT(msg.size(), 200u);
}

TEST(InputLimits, NestingWithinTheLimitReachesTheSchemaCheck) {
  const std::string msg = sceneError("{\"model\": " + nested(20) + "}");
  EXPECT_NE(msg.find("/model"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("nested deeper"), std::string::npos) << msg;
}

TEST(InputLimits, ANumberBeyondADoubleIsAnHpError) {
  EXPECT_ERROR_CONTAINS(parseScene(R"({"camera": {"distance": 1e400}})", "scene.json", "/"),
                        "scene.json: invalid JSON: number overflow");
}

TEST(InputLimits, ANumberBeyondAFloatNamesItsField) {
  EXPECT_ERROR_CONTAINS(parseScene(R"({"camera": {"distance": 1e300}})", "scene.json", "/"),
                        "scene.json: /camera/distance: the number");
  EXPECT_ERROR_CONTAINS(parseScene(R"({"light": {"direction": [0, 1e300, 0]}})", "scene.json", "/"),
                        "scene.json: /light/direction/1: the number does not fit a 32-bit float");
}

TEST(InputLimits, MessagesQuoteOnlyAnExcerptOfHugeKeysAndStrings) {
  const std::string huge(100000, 'k');
  std::string msg = sceneError("{\"" + huge + "\": 1}");
  EXPECT_NE(msg.find("unknown key"), std::string::npos) << msg.substr(0, 200);
  EXPECT_LT(msg.size(), 200u);
  msg = sceneError("{\"model\": {\"source\": \"" + huge + "\"}}");
  EXPECT_NE(msg.find("expected \"default\""), std::string::npos) << msg.substr(0, 200);
  EXPECT_LT(msg.size(), 250u);
  msg = sceneError("{\"light\": {\"type\": \"" + huge + "\"}}");
  EXPECT_LT(msg.size(), 250u);
}

TEST(InputLimits, ExcerptCutsAndEscapes) {
  EXPECT_EQ(excerpt("short"), "short");
  EXPECT_EQ(excerpt(std::string(100, 'a'), 4), "aaaa...");
  EXPECT_EQ(excerpt(std::string("a\nb\0c", 5)), "a\\x0ab\\x00c");
}

TEST(InputLimits, DeviceFilesAndFifosAreNotRead) {
  EXPECT_ERROR_CONTAINS(readInputBytes("/dev/zero", kMaxHairFileBytes), "/dev/zero: cannot open (not a regular file)");
  EXPECT_ERROR_CONTAINS(readHairFile("/dev/zero"), "not a regular file");
  EXPECT_ERROR_CONTAINS(loadSceneFile("/dev/zero"), "not a regular file");
  EXPECT_ERROR_CONTAINS(loadObjScalp("/dev/zero"), "not a regular file");
  // The .tfx reader read /dev/zero until memory ran out, hung on a FIFO and named no path for a folder.
  EXPECT_ERROR_CONTAINS(readTfxFile("/dev/zero"), "/dev/zero: cannot open (not a regular file)");
  test::TempDir dir;
  EXPECT_ERROR_CONTAINS(readTfxFile(dir.path()), dir.path().string() + ": cannot open (not a regular file: a directory)");
  const std::filesystem::path fifo = dir / "pipe.tfx";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_ERROR_CONTAINS(readTfxFile(fifo), fifo.string() + ": cannot open (not a regular file)");
}

TEST(InputLimits, AFileOverItsLimitIsRefusedBeforeReading) {
  test::TempDir dir;
  test::writeText(dir / "big.json", std::string(2048, ' ') + "{}");
  EXPECT_ERROR_CONTAINS(readInputText(dir / "big.json", 1024), "the file is 2050 bytes, more than the 1024 bytes");
  EXPECT_EQ(readInputText(dir / "big.json", 4096).size(), 2050u);
}

TEST(InputLimits, ObjMaterialLibrariesAreNeverOpened) {
  test::TempDir dir;
  // Before, tinyobjloader followed mtllib and read /dev/zero until memory ran out.
  test::writeText(dir / "scalp.obj", std::string("mtllib ../../../../../../dev/zero\nusemtl skin\n") + kTriangleObj);
  ScalpMesh mesh = loadObjScalp(dir / "scalp.obj");
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

// A vertex line that is not 3 finite numbers is refused with its line: the parser read a missing or unreadable
// coordinate as 0 ("v 0.05", "v abc 0 0", "v nan nan nan" became points at the origin).
TEST(InputLimits, ObjVerticesThatAreNotThreeFiniteNumbersAreRefused) {
  for (const char* bad : {"v 1e999 0 0", "v nan nan nan", "v inf 0 0", "v abc 0 0", "v 0.05", "v 1 2 3 4 5 6 7 8"}) {
    const std::string text = std::string("v 1 0 0\n") + bad + "\nv 0 1 0\nf 1 2 3\n";
    EXPECT_ERROR_CONTAINS(parseObjScalp(text, "x.obj"), "x.obj: line 2: a vertex needs 3 finite coordinates, got 'v ");
  }
  // A corner index that does not fit 32 bits (it wrapped into some index: "a non-manifold edge").
  EXPECT_ERROR_CONTAINS(parseObjScalp("v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 99999999999999999999\n", "x.obj"),
                        "x.obj: face 1: corner '99999999999999999999' is not a vertex index");
  EXPECT_ERROR_CONTAINS(parseObjScalp("v 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 x/1\n", "x.obj"), "is not a vertex index");
  const ScalpMesh signs = parseObjScalp("v +1 0 0 # signed\nv .5 1 -1e-3 1.0\nv\t0 0 1\nf 1 2 3\n", "x.obj");
  EXPECT_EQ(signs.positions.size(), 3u);
}

// Lines end at LF, CRLF or a lone CR, as the parser reads them: a CR-only file is checked line by line (one
// long "comment" line let every check pass while the parser read the statements), and a coordinate too small
// for a float is the parser's 0, not an error.
TEST(InputLimits, ObjChecksSeeTheLinesTheParserReads) {
  EXPECT_ERROR_CONTAINS(parseObjScalp("# c\rv 1 0 0\rv 0 1 0\rv 0 0 1\rf 1 2 99999999999999999999\r", "x.obj"),
                        "x.obj: face 1: corner '99999999999999999999' is not a vertex index");
  EXPECT_ERROR_CONTAINS(parseObjScalp("v 1 0 0\r\nv 0.05\r\nv 0 0 1\r\nf 1 2 3\r\n", "x.obj"), "x.obj: line 2: a vertex");
  EXPECT_EQ(parseObjScalp("v 1 0 0\rv 0 1 1e-50\rv 0 0 1\rf +1 2 3\r", "x.obj").positions.size(), 3u);
}
}  // namespace
}  // namespace hp
