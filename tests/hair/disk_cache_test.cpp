// The disk cache (engine/core/disk_cache.h): a value comes back only for its own kind and key from this build;
// damaged, truncated, foreign and colliding entries are misses; a folder that cannot be written is no cache at all;
// a store replaces links rather than writing through them and removes other builds' entries of its kind, old
// temporaries and its least recently used entries past a budget, and nothing else.
#include <gtest/gtest.h>

#include <array>
#include <chrono>

#include "engine/core/build_identity.h"
#include "engine/core/byte_stream.h"
#include "engine/core/disk_cache.h"
#include "engine/core/fnv1a.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
std::vector<std::byte> bytesOf(const std::string& s) {
  const auto b = std::as_bytes(std::span(s.data(), s.size()));
  return {b.begin(), b.end()};
}

std::size_t entries(const std::filesystem::path& folder) {
  return std::size_t(std::distance(std::filesystem::directory_iterator(folder), {}));
}

TEST(DiskCache, GivesBackWhatWasStoredForTheSameKindAndKeyOnly) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  const auto key = bytesOf("material 1"), value = bytesOf("tables");
  EXPECT_FALSE(cache.load("tables", key));
  cache.store("tables", key, value);
  const ino_t stored = test::inodeOf(cache.entryPath("tables", key));
  EXPECT_EQ(cache.load("tables", key), value);
  EXPECT_EQ(test::inodeOf(cache.entryPath("tables", key)), stored) << "a load rewrote the entry";
  EXPECT_FALSE(cache.load("tables", bytesOf("material 2")));
  EXPECT_FALSE(cache.load("transfer", key));
  EXPECT_EQ(entries(dir.path()), 1u);
  cache.store("tables", key, bytesOf("newer"));  // replaced whole
  EXPECT_EQ(cache.load("tables", key), bytesOf("newer"));
  cache.store("tables", bytesOf("empty"), {});
  EXPECT_EQ(cache.load("tables", bytesOf("empty")), std::vector<std::byte>{});
}

TEST(DiskCache, IsOffWithoutAFolder) {
  const DiskCache off{std::filesystem::path()};
  EXPECT_FALSE(off.enabled());
  off.store("tables", bytesOf("k"), bytesOf("v"));
  EXPECT_FALSE(off.load("tables", bytesOf("k")));
}

// Every byte of an entry matters: a flipped byte anywhere, a cut anywhere, an empty file are misses.
TEST(DiskCache, ADamagedOrTruncatedEntryIsAMiss) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  const auto key = bytesOf("key"), value = bytesOf("a value of a few bytes");
  cache.store("tables", key, value);
  const std::filesystem::path path = cache.entryPath("tables", key);
  const std::vector<std::byte> whole = test::readBytes(path);
  for (std::size_t i = 0; i < whole.size(); ++i) {
    std::vector<std::byte> damaged = whole;
    damaged[i] ^= std::byte{0x20};
    test::writeBytes(path, damaged);
    EXPECT_FALSE(cache.load("tables", key)) << "byte " << i << " flipped";
    test::writeBytes(path, std::vector<std::byte>(whole.begin(), whole.begin() + std::ptrdiff_t(i)));
    EXPECT_FALSE(cache.load("tables", key)) << "cut at byte " << i;
  }
  test::writeBytes(path, whole);
  EXPECT_EQ(cache.load("tables", key), value);
}

// Two keys whose entries share a file name (a hash collision, simulated by moving one entry onto the other's
// name): the stored key is compared whole.
TEST(DiskCache, AnEntryForAnotherKeyUnderTheSameNameIsAMiss) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  cache.store("tables", bytesOf("a"), bytesOf("value of a"));
  std::filesystem::rename(cache.entryPath("tables", bytesOf("a")), cache.entryPath("tables", bytesOf("b")));
  EXPECT_FALSE(cache.load("tables", bytesOf("b")));
}

// A whole, well-formed entry with a valid checksum, but made by another build or C library (the identity inside),
// or for another kind: a miss. The layout is the one disk_cache.cpp writes.
TEST(DiskCache, AWholeEntryMadeByAnotherBuildOrForAnotherKindIsAMiss) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  const auto key = bytesOf("key"), value = bytesOf("value");
  cache.store("tables", key, value);
  const std::filesystem::path path = cache.entryPath("tables", key);
  const std::vector<std::byte> ours = test::readBytes(path);
  ByteReader in{std::span(ours).first(ours.size() - 8)};
  in.get<std::array<char, 8>>();
  const std::string identity = in.getString();
  EXPECT_EQ(identity.rfind(buildIdentity(), 0), 0u) << identity;
  auto forged = [&](const std::string& madeBy, const std::string& kind) {
    ByteWriter out;
    out.put(std::array<char, 8>{'h', 'p', 'c', 'a', 'c', 'h', 'e', '2'});
    out.putString(madeBy);
    out.putString(kind);
    out.putVector(std::span<const std::byte>(key));
    out.putVector(std::span<const std::byte>(value));
    out.put(fnv1a(out.bytes()));
    return out.take();
  };
  ASSERT_EQ(forged(identity, "tables"), ours) << "the layout written is not the one this test forges";
  test::writeBytes(path, forged(identity + " (another machine's glibc)", "tables"));
  EXPECT_FALSE(cache.load("tables", key));
  test::writeBytes(path, forged(identity, "transfer"));
  EXPECT_FALSE(cache.load("tables", key));
  test::writeBytes(path, forged(identity, "tables"));
  EXPECT_EQ(cache.load("tables", key), value);
}

// A link at an entry's path is replaced by the entry, never written through: the file it names stays as it was.
TEST(DiskCache, ALinkAtAnEntrysPathIsReplacedNotWrittenThrough) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "cache");
  const DiskCache cache(dir / "cache");
  test::writeText(dir / "victim", "the user's file");
  std::filesystem::create_symlink(dir / "victim", cache.entryPath("tables", bytesOf("k")));
  EXPECT_FALSE(cache.load("tables", bytesOf("k")));
  cache.store("tables", bytesOf("k"), bytesOf("v"));
  EXPECT_EQ(test::readBytes(dir / "victim"), bytesOf("the user's file"));
  EXPECT_FALSE(std::filesystem::is_symlink(cache.entryPath("tables", bytesOf("k"))));
  EXPECT_EQ(cache.load("tables", bytesOf("k")), bytesOf("v"));
}

// A link at an entry's path is not followed on reading, even to a whole entry of the same key elsewhere.
TEST(DiskCache, ALinkToAValidEntryIsNotRead) {
  test::TempDir dir;
  std::filesystem::create_directory(dir / "elsewhere");
  std::filesystem::create_directory(dir / "cache");
  const DiskCache elsewhere(dir / "elsewhere"), cache(dir / "cache");
  elsewhere.store("tables", bytesOf("k"), bytesOf("v"));
  ASSERT_EQ(elsewhere.load("tables", bytesOf("k")), bytesOf("v"));
  std::filesystem::create_symlink(elsewhere.entryPath("tables", bytesOf("k")), cache.entryPath("tables", bytesOf("k")));
  EXPECT_FALSE(cache.load("tables", bytesOf("k")));
}

// Past its byte budget a kind loses its least recently used entries; a load counts as a use.
TEST(DiskCache, AKindKeepsItsMostRecentlyUsedEntriesWithinItsBudget) {
  test::TempDir dir;
  const std::vector<std::byte> value(1000, std::byte{7});
  const DiskCache cache(dir.path(), 2500);  // two entries of ~1.1 KB fit, three do not
  const auto hourAgo = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  cache.store("tables", bytesOf("a"), value);
  cache.store("tables", bytesOf("b"), value);
  std::filesystem::last_write_time(cache.entryPath("tables", bytesOf("a")), hourAgo - std::chrono::minutes(1));
  std::filesystem::last_write_time(cache.entryPath("tables", bytesOf("b")), hourAgo);
  EXPECT_TRUE(cache.load("tables", bytesOf("a")));  // a used now: b is the least recent
  cache.store("tables", bytesOf("c"), value);
  EXPECT_TRUE(cache.load("tables", bytesOf("a")));
  EXPECT_FALSE(cache.load("tables", bytesOf("b")));
  EXPECT_TRUE(cache.load("tables", bytesOf("c")));
  cache.store("transfer", bytesOf("a"), value);  // another kind has its own budget
  EXPECT_TRUE(cache.load("tables", bytesOf("a")));
  EXPECT_TRUE(cache.load("tables", bytesOf("c")));
}

// A temporary a process left when it died while writing goes once it is old; a recent one may be another
// process's write in progress and stays.
TEST(DiskCache, AStoreRemovesTemporariesLeftByDeadWriters) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  const std::string entry = cache.entryPath("tables", bytesOf("k")).filename().string();
  const std::filesystem::path old = dir / ("." + entry + ".tmp-abc123"), recent = dir / ("." + entry + ".tmp-def456");
  test::writeText(old, "half an entry");
  test::writeText(recent, "half an entry");
  std::filesystem::last_write_time(old, std::filesystem::file_time_type::clock::now() - std::chrono::minutes(11));
  cache.store("tables", bytesOf("other"), bytesOf("v"));
  EXPECT_FALSE(std::filesystem::exists(old));
  EXPECT_TRUE(std::filesystem::exists(recent));
}

TEST(DiskCache, AFolderThatCannotBeWrittenIsNoCacheAndNoError) {
  test::TempDir dir;
  test::writeText(dir / "file", "a file, not a folder");
  const DiskCache underFile(dir / "file" / "cache");
  EXPECT_NO_THROW(underFile.store("tables", bytesOf("k"), bytesOf("v")));
  EXPECT_FALSE(underFile.load("tables", bytesOf("k")));
  if (::geteuid() != 0) {  // root writes anywhere
    std::filesystem::create_directory(dir / "locked");
    std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    const DiskCache locked(dir / "locked");
    EXPECT_NO_THROW(locked.store("tables", bytesOf("k"), bytesOf("v")));
    EXPECT_FALSE(locked.load("tables", bytesOf("k")));
  }
}

// Something at an entry's path that is not a regular file (a FIFO would block a read forever) is a miss.
TEST(DiskCache, AFifoOrFolderAtAnEntrysPathIsAMiss) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  ASSERT_EQ(::mkfifo(cache.entryPath("tables", bytesOf("fifo")).c_str(), 0600), 0);
  EXPECT_FALSE(cache.load("tables", bytesOf("fifo")));
  std::filesystem::create_directory(cache.entryPath("tables", bytesOf("folder")));
  EXPECT_FALSE(cache.load("tables", bytesOf("folder")));
}

// Another build's entry of the kind goes; this build's entry made on another machine (its C library's part of the
// identity: the name's 8-digit field) stays, as do other kinds' entries, names that only look like entries, and the
// user's files.
TEST(DiskCache, AStoreRemovesOtherBuildsEntriesOfItsKindOnly) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  const std::string otherBuild(32, 'f'), otherMachine(8, '0'), hash(16, '0');
  ASSERT_NE(otherBuild, buildIdentity());
  const std::string older = "tables-" + otherBuild + "-" + otherMachine + "-" + hash + ".bin";
  const std::string otherKind = "transfer-" + otherBuild + "-" + otherMachine + "-" + hash + ".bin";
  const std::string otherMachines = "tables-" + std::string(buildIdentity()) + "-" + otherMachine + "-" + hash + ".bin";
  const std::string notHex = "tables-" + std::string(32, 'g') + "-" + otherMachine + "-" + hash + ".bin";
  for (const std::string& name : {older, otherKind, otherMachines, notHex, std::string("notes.txt")})
    test::writeText(dir / name, "some bytes");
  cache.store("tables", bytesOf("kept"), bytesOf("v"));
  cache.store("tables", bytesOf("kept too"), bytesOf("w"));
  EXPECT_FALSE(std::filesystem::exists(dir / older));
  for (const std::string& name : {otherKind, otherMachines, notHex, std::string("notes.txt")})
    EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
  EXPECT_EQ(cache.load("tables", bytesOf("kept")), bytesOf("v"));
  EXPECT_EQ(cache.load("tables", bytesOf("kept too")), bytesOf("w"));
}

TEST(DiskCache, KindsAreNamesForFiles) {
  test::TempDir dir;
  const DiskCache cache(dir.path());
  EXPECT_ERROR_CONTAINS(cache.entryPath("../escape", bytesOf("k")), "kind '../escape'");
  EXPECT_ERROR_CONTAINS(cache.entryPath("", bytesOf("k")), "kind ''");
  cache.store("Tables/x", bytesOf("k"), bytesOf("v"));  // refused quietly: nothing written
  EXPECT_EQ(entries(dir.path()), 0u);
}

TEST(ByteStream, ReadsBackWhatWasWritten) {
  ByteWriter out;
  out.put(std::uint32_t(7));
  out.putString("name");
  out.putVector(std::vector<float>{1.5f, -2.0f});
  out.put(3.25);
  const std::vector<std::byte> bytes = out.take();
  ByteReader in(bytes);
  EXPECT_EQ(in.get<std::uint32_t>(), 7u);
  EXPECT_EQ(in.getString(), "name");
  EXPECT_EQ(in.getVector<float>(), (std::vector<float>{1.5f, -2.0f}));
  EXPECT_EQ(in.get<double>(), 3.25);
  EXPECT_TRUE(in.atEnd());
}

// A length that claims more than the stream holds is refused before anything is allocated.
TEST(ByteStream, ALengthBeyondTheDataIsRefusedNamingTheValue) {
  ByteWriter out;
  out.put(std::uint64_t(1) << 60);
  const std::vector<std::byte> bytes = out.take();
  ByteReader in(bytes, "entry.bin");
  EXPECT_ERROR_CONTAINS(in.getVector<double>("the texels"), "entry.bin: the texels needs");
  ByteReader empty(std::span<const std::byte>{}, "empty.bin");
  EXPECT_ERROR_CONTAINS(empty.get<std::uint32_t>("the count"), "empty.bin: the count needs 4 bytes at byte 0, the file has 0 left");
}
}  // namespace
}  // namespace hp
