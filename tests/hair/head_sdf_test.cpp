// The default head's signed distance field and its marching-cubes mesh: a closed, consistently wound
// mesh on the zero level set, with the silhouette of a head and shoulders (nose in profile, neck
// narrower than the head, shoulders wider), built deterministically.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_sdf.h"
#include "engine/core/hair/sdf_primitives.h"
#include "engine/core/hair/level_set_mesh.h"

namespace hp {
namespace {
const NarrowBandGrid& field() {
  static const NarrowBandGrid f = makeDefaultHeadField();
  return f;
}
const SdfGrid& grid() { return field().grid; }
const HeadMesh& mesh() {
  static const HeadMesh m = makeDefaultHeadMesh(field());
  return m;
}

// Widest |x| (or z extent) of the field's inside at height y, scanning the grid's nodes.
struct Extent {
  float xMax = 0.0f, zMin = 1.0f, zMax = -1.0f;
};
Extent extentAt(float y) {
  Extent e;
  const auto j = std::uint32_t(std::lround((y - grid().origin.y) / grid().cell));
  for (std::uint32_t k = 0; k < grid().dims.z; ++k)
    for (std::uint32_t i = 0; i < grid().dims.x; ++i)
      if (grid().at(i, j, k) < 0.0f) {
        const glm::vec3 p = grid().node(i, j, k);
        e.xMax = std::max(e.xMax, std::abs(p.x));
        e.zMin = std::min(e.zMin, p.z);
        e.zMax = std::max(e.zMax, p.z);
      }
  return e;
}

// Largest z of the inside at (x, y): the profile seen from the side (x = 0: the midline).
float profileAt(float y, float x = 0.0f) {
  float z = -1.0f;
  for (float s = -0.16f; s < 0.16f; s += 0.0005f)
    if (headDistance({x, y, s}) < 0.0f) z = s;
  return z;
}
}  // namespace

TEST(HeadSdf, MeshIsClosedAndConsistentlyWound) {
  const HeadMesh& m = mesh();
  ASSERT_GT(m.indices.size(), 3000u);
  ASSERT_EQ(m.indices.size() % 3, 0u);
  // Every directed edge exactly once, and its reverse exactly once: closed (watertight) and every
  // pair of neighbouring triangles wound the same way.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) ++directed[{m.indices[t + e], m.indices[t + (e + 1) % 3]}];
  std::size_t bad = 0;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    bad += count != 1 || reverse == directed.end() || reverse->second != 1;
  }
  EXPECT_EQ(bad, 0u) << "of " << directed.size() << " directed edges";
}

TEST(HeadSdf, WindingAndNormalsPointOutOfTheField) {
  const HeadMesh& m = mesh();
  std::size_t disagree = 0;
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]], c = m.positions[m.indices[t + 2]];
    const glm::vec3 face = glm::cross(b - a, c - a);
    const glm::vec3 n = m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
    if (glm::length(face) > 1e-12f) disagree += glm::dot(face, n) <= 0.0f;
  }
  EXPECT_EQ(disagree, 0u);
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    ASSERT_NEAR(glm::length(m.normals[v]), 1.0f, 1e-4f);
    // Stepping out along the normal leaves the head.
    ASSERT_GT(headDistance(m.positions[v] + 0.001f * m.normals[v]), 0.0f) << "vertex " << v;
  }
}

TEST(HeadSdf, VerticesLieOnTheZeroLevelSet) {
  float worst = 0.0f;
  for (const auto& p : mesh().positions) worst = std::max(worst, std::abs(headDistance(p)));
  EXPECT_LT(worst, 0.5f * kDefaultHeadCell);
}

TEST(HeadSdf, GridIsTheFieldInTheBandAndCorrectlySignedBeyond) {
  // Every node within the band holds the field's value itself; every other node has the field's sign
  // and a magnitude above the band (a far node holds a blend of exact values, a near one the field).
  std::size_t wrongInBand = 0, wrongBeyond = 0, inBand = 0, farNodes = 0;
  for (std::uint32_t k = 0; k < grid().dims.z; ++k)
    for (std::uint32_t j = 0; j < grid().dims.y; ++j)
      for (std::uint32_t i = 0; i < grid().dims.x; ++i) {
        const float f = headDistance(grid().node(i, j, k)), v = grid().at(i, j, k);
        if (std::abs(f) <= kDefaultHeadBand) {
          ++inBand;
          wrongInBand += v != f;
        } else {
          farNodes += v != f;
          wrongBeyond += (v < 0.0f) != (f < 0.0f) || std::abs(v) <= kDefaultHeadBand;
        }
      }
  EXPECT_EQ(wrongInBand, 0u) << "of " << inBand;
  EXPECT_EQ(wrongBeyond, 0u);
  EXPECT_GT(inBand, 50000u);
  EXPECT_GT(farNodes, grid().values.size() / 2);  // the far field is not evaluated node by node
  EXPECT_LT(field().exactNodes, grid().values.size() / 3);
}

TEST(HeadSdf, GridSamplesTheFieldTrilinearly) {
  // Between the nodes the grid is close to the field (the field is smooth at this scale).
  float worst = 0.0f;
  for (const auto& p : mesh().positions) worst = std::max(worst, std::abs(grid().sample(p)));
  EXPECT_LT(worst, 0.3f * kDefaultHeadCell);
  // Outside the box the grid keeps growing.
  EXPECT_GT(grid().sample({0.0f, 1.0f, 0.0f}), 0.8f);
}

TEST(HeadSdf, SilhouetteReadsAsAHeadAndShoulders) {
  const Extent head = extentAt(0.0f), neck = extentAt(-0.17f), shoulders = extentAt(-0.28f);
  EXPECT_GT(head.xMax, 0.065f);  // a head about 15 cm wide (ears included)
  EXPECT_LT(head.xMax, 0.095f);
  EXPECT_LT(neck.xMax, 0.8f * head.xMax);        // front view: the neck is narrower than the head
  EXPECT_GT(shoulders.xMax, 2.0f * head.xMax);   // and the shoulders much wider
  EXPECT_LT(neck.zMax - neck.zMin, head.zMax - head.zMin);  // side view: the neck is thinner too
  // Profile: the nose tip stands out of the face above and below it, the chin below the mouth.
  const float nose = profileAt(-0.038f), brow = profileAt(0.02f), upperLip = profileAt(-0.062f);
  EXPECT_GT(nose, brow + 0.012f);
  EXPECT_GT(nose, upperLip + 0.012f);
  EXPECT_GT(profileAt(-0.11f), 0.07f);  // a chin, not a receding blob
  // Back view: the back of the skull is round and behind the neck.
  EXPECT_LT(head.zMin, neck.zMin - 0.03f);
  // Eye sockets: above the eye the brow stands out of the surface.
  EXPECT_LT(profileAt(0.0f, 0.031f), profileAt(0.02f, 0.031f) - 0.002f);
}

TEST(HeadSdf, EarsStandOutAtTheSides) {
  // At ear height, just behind the cheek, the head is wider than just above the ear.
  const float atEar = [] {
    float x = 0.0f;
    for (float s = 0.0f; s < 0.12f; s += 0.0005f)
      if (headDistance({s, -0.018f, -0.012f}) < 0.0f) x = s;
    return x;
  }();
  float above = 0.0f;
  for (float s = 0.0f; s < 0.12f; s += 0.0005f)
    if (headDistance({s, 0.045f, -0.012f}) < 0.0f) above = s;
  EXPECT_GT(atEar, above + 0.01f);
}

TEST(HeadSdf, BuildIsDeterministic) {
  const NarrowBandGrid f = makeDefaultHeadField();
  EXPECT_EQ(f.grid.values, grid().values);
  const HeadMesh again = makeDefaultHeadMesh(f);
  EXPECT_EQ(again.positions, mesh().positions);
  EXPECT_EQ(again.normals, mesh().normals);
  EXPECT_EQ(again.indices, mesh().indices);
}

TEST(HeadSdf, RaysFromTheCraniumMeetTheSurfaceWithItsGradient) {
  // Directions over the upper half (the scalp's) and one straight down into the chest, which is still
  // inside 0.3 m out: the first ones land within 0.1 um of the surface with headGradient there, the last
  // returns the bracket's outer end.
  std::vector<glm::vec3> dirs;
  for (int i = 0; i < 200; ++i) {
    const float azimuth = 0.0314f * float(i), elevation = 0.1f + 1.3f * float(i % 17) / 17.0f;
    dirs.push_back({std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)});
  }
  dirs.push_back({0.0f, -1.0f, 0.0f});
  std::vector<glm::vec3> surfaces(dirs.size()), gradients(dirs.size());
  headSurfacesAlong(dirs, surfaces, gradients);
  for (std::size_t i = 0; i + 1 < dirs.size(); ++i) {
    ASSERT_LT(std::abs(headDistance(surfaces[i])), 1e-7f) << "ray " << i;
    ASSERT_EQ(gradients[i], headGradient(surfaces[i])) << "ray " << i;
  }
  EXPECT_LT(headDistance(kCraniumCenter + 0.3f * dirs.back()), 0.0f);
  EXPECT_EQ(surfaces.back(), kCraniumCenter + 0.3f * dirs.back());
  std::vector<glm::vec3> alone(1);
  headSurfacesAlong(std::span(dirs).first(1), alone, {});  // no gradients asked: the same point
  EXPECT_EQ(alone[0], surfaces[0]);
  try {
    headSurfacesAlong(dirs, std::span(surfaces).first(3), {});
    ADD_FAILURE() << "a short span of surface points was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("one surface point"), std::string::npos) << e.what();
  }
}

TEST(HeadSdf, SurfaceNetsRefuseASurfaceCutByTheGrid) {
  auto ball = [](const glm::vec3& p) { return sdf::sphere(p, glm::vec3(0.0f), 1.0f); };
  EXPECT_THROW(meshZeroLevel(sampleField(ball, glm::vec3(-1.2f, -1.2f, -0.5f), glm::vec3(1.2f), 0.1f), ball), Error);
  const HeadMesh whole = meshZeroLevel(sampleField(ball, glm::vec3(-1.3f), glm::vec3(1.3f), 0.1f), ball);
  EXPECT_GT(whole.indices.size(), 100u);
}
}  // namespace hp
