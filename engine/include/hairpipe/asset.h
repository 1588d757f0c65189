#pragma once
// Contract: a head of hair as data, before any device sees it: guide strands (their rest pose), the
// scalp triangles that interpolate render strands between guides, the colliders and distance field the
// hair stays outside of, and the head mesh drawn with it. Immutable once made; an Asset is a shared
// handle, cheap to copy, and one asset may back any number of instances on any number of renderers.
// Made by loadAsset (a .hair, TressFX .tfx or scalp .obj file, with a character mesh if given) or
// defaultHeadAsset (the procedural head).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hairpipe/math.h"
#include "hairpipe/result.h"

namespace hp {
struct HairAsset;  // the implementation (private)
}

namespace hairpipe {
struct Access;

// How many render strands are interpolated between the guides.
struct Density {
  // Guides: one render strand on every guide (a model's own strands, in its own shape). Auto: Guides when the
  // asset has at least totalStrands guides (a model with many strands draws its own), else Total.
  enum class Mode { PerTriangle, Total, Guides, Auto };
  Mode mode = Mode::Total;
  std::uint32_t strandsPerTriangle = 8;  // PerTriangle
  std::uint32_t totalStrands = 20000;    // Total: spread in proportion to the triangles' areas
  std::uint32_t seed = 7;                // the strands' placement is reproducible for a seed
};

enum class UpAxis { Y, Z };

struct AssetSource {
  std::string path;          // .hair (Cem Yuksel's format), .tfx (TressFX) or .obj (a scalp to grow guides on)
  float scale = 1.0f;        // model units to scene units (centimetres to metres: 0.01)
  UpAxis up = UpAxis::Y;     // the model's up axis; Z-up models are rotated to Y up
  Vec3 translation{};        // after scale and rotation
  bool keepStrands = false;  // .hair/.tfx: keep each strand's own points instead of resampling to guides
  Density density{Density::Mode::Auto};  // by default a model of at least 20000 strands draws its own
  // A character mesh for the model (.obj, .ply, .gltf, .glb or TressFX .tfxmesh; "" none), in the model's units
  // and axes (scale, up and translation apply to it too): drawn as the head, the distance grid the hair
  // collides with (instead of a sphere fitted to the roots), and the surface the guides' roots bind to.
  std::string mesh;
  float meshCell = 0.0f;  // its distance grid's spacing (scene units); 0: 1/128 of the mesh's longest side
};

// A character mesh as loaded (AssetSource::mesh) and how the asset's guide roots bound to it: each to its
// nearest triangle; roots farther than farDistance (2% of the mesh's diagonal) are counted, not moved.
struct CharacterInfo {
  std::uint32_t vertices = 0, triangles = 0;
  std::vector<std::string> jointNames;  // the skeleton (empty: a rigid mesh)
  std::vector<std::string> clipNames;   // its animation clips (glTF)
  std::uint32_t farRoots = 0;
  float farDistance = 0.0f, meanRootDistance = 0.0f, maxRootDistance = 0.0f;
};

class Asset {
 public:
  // Copies share the data. A moved-from Asset counts nothing and fails where a value is asked of it.
  std::uint32_t guideCount() const noexcept;
  std::uint32_t particlesPerGuide() const noexcept;
  std::uint32_t strandCount() const noexcept;  // render strands of the asset's interpolation topology
  std::uint32_t headTriangleCount() const noexcept;
  // Scalp triangles an imported model's roots form that were left without render strands: their guides part
  // around the head (a parting, a whorl), so any blend of them would run through it (0 for the default head,
  // whose parting is left open by construction). Counted for every density: an asset drawing its own strands
  // shows no scalp bare (it blends over no triangle) but has these dropped all the same, so that one made from
  // it by withDensity() blends over none of them.
  std::uint32_t bareScalpTriangleCount() const noexcept;
  Result<std::vector<Vec3>> guideRoots() const noexcept;  // head space, one per guide (for skinning weights)
  const char* name() const noexcept;
  // The character mesh the asset was loaded with; fails when it has none.
  Result<CharacterInfo> character() const noexcept;
  // The same guides and head with another density of render strands.
  Result<Asset> withDensity(const Density& density) const noexcept;

 private:
  friend struct Access;  // hairpipe's implementation
  explicit Asset(std::shared_ptr<const hp::HairAsset> impl) noexcept : impl_(std::move(impl)) {}
  std::shared_ptr<const hp::HairAsset> impl_;
};

// Reads a model file through hairpipe's bounded readers (size and count limits; a clear failure naming
// the file and the problem for anything malformed).
Result<Asset> loadAsset(const AssetSource& source) noexcept;
// The procedural default head (its scalp, head mesh and distance field) with guides grown on it.
Result<Asset> defaultHeadAsset(const Density& density = {}) noexcept;
}  // namespace hairpipe
