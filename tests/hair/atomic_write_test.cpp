// Atomic file output: whole file or nothing, no temporary left behind.
#include <gtest/gtest.h>

#include "engine/core/hair/atomic_write.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
std::vector<std::byte> bytes(const std::string& s) {
  std::vector<std::byte> b(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) b[i] = std::byte(s[i]);
  return b;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), {}};
}

TEST(HairAtomicWrite, WritesAndReplaces) {
  test::TempDir dir;
  writeFileAtomically(dir / "f.bin", bytes("first"));
  writeFileAtomically(dir / "f.bin", bytes("second"));
  EXPECT_EQ(slurp(dir / "f.bin"), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(HairAtomicWrite, FailureLeavesNoTemporary) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "taken");
  std::filesystem::create_directory(dir / "taken" / "sub");  // a non-empty directory cannot be replaced
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "taken", bytes("x")), "taken: cannot write: ");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "missing" / "f.bin", bytes("x")),
                        "f.bin: cannot create a temporary file");
}
}  // namespace
}  // namespace hp
