// Atomic file output: whole file or nothing, no temporary left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>

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
  std::filesystem::create_directory(dir / "taken" / "sub");  // a folder is never replaced
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "taken", bytes("x")), "taken: exists and is not a regular file");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "missing" / "f.bin", bytes("x")),
                        "f.bin: cannot create a temporary file");
}

// A link is followed (its target written, the link kept); a FIFO (as a device such as /dev/null) is refused and
// stays what it was: renaming over it replaced it with a regular file, and as root would replace /dev/null.
TEST(HairAtomicWrite, FollowsLinksAndNeverReplacesWhatIsNotARegularFile) {
  test::TempDir dir;
  writeFileAtomically(dir / "target.bin", bytes("old"));
  std::filesystem::create_symlink(dir / "target.bin", dir / "link.bin");
  writeFileAtomically(dir / "link.bin", bytes("new"));
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.bin"));
  EXPECT_EQ(slurp(dir / "target.bin"), "new");
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "pipe", bytes("x")), "pipe: exists and is not a regular file");
  EXPECT_EQ(std::filesystem::status(dir / "pipe").type(), std::filesystem::file_type::fifo);
  std::filesystem::create_symlink(dir / "gone.bin", dir / "dangling.bin");
  EXPECT_ERROR_CONTAINS(writeFileAtomically(dir / "dangling.bin", bytes("x")), "is a link that cannot be followed");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 4);  // no temporary left
}
}  // namespace
}  // namespace hp
