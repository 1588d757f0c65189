// The mesh simplification through the disk cache (engine/core/hair/mesh_simplify_cache.h): read back exactly what
// simplifying gives, keyed by the whole mesh and the options (a change to either is another entry), a damaged
// entry simplified again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/hair/head_mesh_bytes.h"
#include "engine/core/hair/mesh_simplify_cache.h"
#include "tests/hair/hair_test_util.h"

using namespace hp;

namespace {
// An n x n grid of unit cells in the xy plane with a bump in the middle, facing +z, scalp weights 0.
HeadMesh bumpedSheet(std::uint32_t n) {
  HeadMesh mesh;
  for (std::uint32_t j = 0; j <= n; ++j)
    for (std::uint32_t i = 0; i <= n; ++i) {
      const float dx = float(i) - 0.5f * float(n), dy = float(j) - 0.5f * float(n);
      mesh.positions.push_back({float(i), float(j), 2.0f / (1.0f + dx * dx + dy * dy)});
      mesh.normals.push_back({0.0f, 0.0f, 1.0f});
    }
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
    }
  mesh.scalp.assign(mesh.positions.size(), 0.0f);
  return mesh;
}

void expectSame(const HeadMesh& a, const HeadMesh& b) {
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.indices, b.indices);
  EXPECT_EQ(a.scalp, b.scalp);
}

std::size_t entries(const std::filesystem::path& folder) {
  return std::size_t(std::distance(std::filesystem::directory_iterator(folder), {}));
}

const SimplifyOptions kOptions{0.05f, 60.0f, 0};
}  // namespace

TEST(MeshSimplifyCache, ReadsBackWhatSimplifyingGivesKeyedByTheMeshAndTheOptions) {
  test::TempDir dir;
  const DiskCache disk(dir.path());
  const HeadMesh mesh = bumpedSheet(12);
  const HeadMesh simplified = simplifyMesh(mesh, kOptions);
  ASSERT_LT(simplified.indices.size(), mesh.indices.size());  // something to keep
  expectSame(simplifyMeshCached(disk, mesh, kOptions), simplified);  // simplified and stored
  ASSERT_EQ(entries(dir.path()), 1u);
  const std::filesystem::path entry = std::filesystem::directory_iterator(dir.path())->path();
  const ino_t stored = test::inodeOf(entry);
  expectSame(simplifyMeshCached(disk, mesh, kOptions), simplified);  // read back: the entry not written again
  EXPECT_EQ(test::inodeOf(entry), stored) << "simplified again instead of read";
  // Each option and each array of the mesh is in the key: a change to one is another entry, simplified anew.
  const SimplifyOptions otherOptions[] = {{0.5f, 60.0f, 0}, {0.05f, 30.0f, 0}, {0.05f, 60.0f, 150}};
  for (const SimplifyOptions& o : otherOptions) expectSame(simplifyMeshCached(disk, mesh, o), simplifyMesh(mesh, o));
  HeadMesh scalped = mesh, tilted = mesh, turned = mesh, moved = mesh;
  scalped.scalp[3] = 1.0f;
  tilted.normals[3] = glm::normalize(glm::vec3(0.1f, 0.0f, 1.0f));
  std::swap(turned.indices[0], turned.indices[1]);  // one triangle wound the other way
  moved.positions[3].z += 0.01f;
  for (const HeadMesh* m : {&scalped, &tilted, &turned, &moved})
    expectSame(simplifyMeshCached(disk, *m, kOptions), simplifyMesh(*m, kOptions));
  EXPECT_EQ(entries(dir.path()), 8u);
  // No cache: simplified.
  expectSame(simplifyMeshCached(DiskCache(""), mesh, kOptions), simplified);
}

TEST(MeshSimplifyCache, ADamagedEntryIsSimplifiedAgainAndReplaced) {
  test::TempDir dir;
  const DiskCache disk(dir.path());
  const HeadMesh mesh = bumpedSheet(10);
  const HeadMesh simplified = simplifyMeshCached(disk, mesh, kOptions);
  const std::filesystem::path entry = std::filesystem::directory_iterator(dir.path())->path();
  std::filesystem::resize_file(entry, std::filesystem::file_size(entry) / 2);  // a torn write
  const ino_t damaged = test::inodeOf(entry);
  expectSame(simplifyMeshCached(disk, mesh, kOptions), simplifyMesh(mesh, kOptions));
  EXPECT_NE(test::inodeOf(entry), damaged) << "the damaged entry was not replaced";
  expectSame(simplifyMeshCached(disk, mesh, kOptions), simplified);
}

// An entry whose checksum holds but whose mesh is not well formed (a value no simplification gives) is simplified
// again and replaced, never drawn.
TEST(MeshSimplifyCache, AnIllFormedMeshInAnEntryIsSimplifiedAgain) {
  test::TempDir dir;
  const DiskCache disk(dir.path());
  const HeadMesh mesh = bumpedSheet(10);
  HeadMesh bad = simplifyMesh(mesh, kOptions);
  bad.indices[0] = std::uint32_t(bad.positions.size());  // out of range
  ByteWriter value;
  writeHeadMesh(value, bad);
  disk.store(kSimplifiedMeshKind, simplifiedMeshKey(mesh, kOptions), value.bytes());
  ASSERT_EQ(entries(dir.path()), 1u);
  const std::filesystem::path entry = std::filesystem::directory_iterator(dir.path())->path();
  const ino_t planted = test::inodeOf(entry);
  expectSame(simplifyMeshCached(disk, mesh, kOptions), simplifyMesh(mesh, kOptions));
  EXPECT_NE(test::inodeOf(entry), planted) << "the ill-formed entry was kept";
  EXPECT_EQ(entries(dir.path()), 1u);  // the same key: that entry, replaced
}

// What an entry's bytes decode into is drawable: a mesh that is not well formed is refused by name.
TEST(MeshSimplifyCache, MeshBytesRoundTripAndRefuseAnIllFormedMesh) {
  const HeadMesh mesh = bumpedSheet(3);
  ByteWriter out;
  writeHeadMesh(out, mesh);
  ByteReader in(out.bytes());
  expectSame(readHeadMesh(in), mesh);
  EXPECT_TRUE(in.atEnd());
  const auto refusal = [](const HeadMesh& bad) {
    ByteWriter w;
    writeHeadMesh(w, bad);
    ByteReader r(w.bytes());
    try {
      readHeadMesh(r);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  HeadMesh farIndex = mesh;
  farIndex.indices[4] = 16;
  EXPECT_EQ(refusal(farIndex), "head mesh bytes: index 16 past the 16 positions");
  HeadMesh fewNormals = mesh;
  fewNormals.normals.pop_back();
  EXPECT_EQ(refusal(fewNormals), "head mesh bytes: 15 normals for 16 positions");
  HeadMesh partial = mesh;
  partial.indices.pop_back();
  EXPECT_EQ(refusal(partial), "head mesh bytes: 53 indices are not whole triangles");
}
