#include "engine/core/shading/lut_cache.h"

#include <optional>

#include "engine/core/byte_stream.h"
#include "engine/core/recent_cache.h"
#include "engine/core/shading/lut_encoding.h"

namespace hp {
namespace {
struct LutKey {
  LutMode mode;
  HairMaterial material;
  LutFormat floatFormat, paperFormat;
  bool operator==(const LutKey&) const = default;
};

// Every byte of a HairMaterial is a value (no padding), so equal bytes are equal materials.
static_assert(sizeof(HairMaterial) == 13 * sizeof(double));

std::vector<std::byte> keyBytes(const LutKey& key) {
  ByteWriter out;
  out.put(key.mode);
  out.put(key.material);
  out.put(key.floatFormat);
  out.put(key.paperFormat);
  return out.take();
}

constexpr const char* kTablesKind = "marschner-tables";

// The tables kept for `key`, when they decode and are of the mode and material asked for.
std::optional<MarschnerLut> loadFromDisk(const DiskCache& disk, std::span<const std::byte> key, LutMode mode,
                                         const HairMaterial& material) {
  const std::optional<std::vector<std::byte>> value = disk.load(kTablesKind, key);
  if (!value) return std::nullopt;
  try {
    MarschnerLut lut = decodeLut(*value);
    if (lut.mode == mode && lut.material == material) return lut;
  } catch (const Error&) {  // not an encoding: not an entry this build wrote
  }
  return std::nullopt;
}

// A physical model's tables are ~2 MiB; four materials cover a tool comparing looks or a viewer's edits. Never
// destroyed: a material's build on a detached worker (compute/renderer/lut_build.h) may outlive main.
RecentCache<LutKey, MarschnerLut, 4>& luts() {
  static auto& cache = *new RecentCache<LutKey, MarschnerLut, 4>;
  return cache;
}
}  // namespace

MarschnerLut loadOrBuildLut(const DiskCache& disk, LutMode mode, const HairMaterial& material,
                            const LutBuildOptions& options) {
  if (!disk.enabled()) return buildLut(mode, material, options);
  const std::vector<std::byte> key = keyBytes({mode, material, options.floatFormat, options.paperFormat});
  if (std::optional<MarschnerLut> kept = loadFromDisk(disk, key, mode, material)) return std::move(*kept);
  MarschnerLut lut = buildLut(mode, material, options);
  disk.store(kTablesKind, key, encodeLut(lut));
  return lut;
}

std::shared_ptr<const MarschnerLut> sharedLut(LutMode mode, const HairMaterial& material,
                                              const LutBuildOptions& options) {
  const LutKey key{mode, material, options.floatFormat, options.paperFormat};
  return luts().get(key, [&] { return loadOrBuildLut(DiskCache::process(), mode, material, options); });
}
std::uint64_t sharedLutsMade() { return luts().made(); }

RecentCache<LutKey, gpu::MarschnerParams, 4>& marschnerParams() {
  static auto& cache = *new RecentCache<LutKey, gpu::MarschnerParams, 4>;  // never destroyed, as luts()
  return cache;
}

std::shared_ptr<const gpu::MarschnerParams> sharedMarschnerParams(LutMode mode, const HairMaterial& material) {
  const LutBuildOptions defaults;
  return marschnerParams().get(LutKey{mode, material, defaults.floatFormat, defaults.paperFormat},
                               [&] { return marschnerGpuParams(*sharedLut(mode, material)); });
}

std::uint64_t sharedMarschnerParamsMade() { return marschnerParams().made(); }
}  // namespace hp
