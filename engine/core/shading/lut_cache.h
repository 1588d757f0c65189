#pragma once
// Contract: a material's Marschner tables (buildLut), built once per process for the last few (mode, material,
// options) built and shared read-only after. buildLut is a pure function of the three and costs ~0.5 s
// of CPU for the physical model; a process that makes several Renderers, changes a material back and forth
// or recreates its device would otherwise build the same tables again. Thread-safe: a build runs outside the
// lock (two threads asking for the same new tables at once may both build them; both get the first kept).
// Errors are buildLut's (an invalid material throws and nothing is kept). With a disk cache (engine/core/disk_cache.h,
// HAIRPIPE_CACHE_DIR) a process reads tables another process of the same build made instead of building them.
#include <cstdint>
#include <memory>

#include "engine/core/disk_cache.h"
#include "engine/core/shading/lut.h"
#include "engine/core/shading/marschner_gpu.h"

namespace hp {
// The tables from `disk` when it holds them (bit for bit what buildLut gives), else built and kept there.
MarschnerLut loadOrBuildLut(const DiskCache& disk, LutMode mode, const HairMaterial& material,
                            const LutBuildOptions& options = {});
// Tables the process has made for sharedLut (values it kept and handed out again not counted).
std::uint64_t sharedLutsMade();
// The device parameter block of sharedLut's tables (marschnerGpuParams: the sky albedo's quadrature, 12-28 ms
// of CPU), kept for the same last few materials; and how many the process has computed.
std::shared_ptr<const gpu::MarschnerParams> sharedMarschnerParams(LutMode mode, const HairMaterial& material);
std::uint64_t sharedMarschnerParamsMade();
std::shared_ptr<const MarschnerLut> sharedLut(LutMode mode, const HairMaterial& material,
                                              const LutBuildOptions& options = {});
}  // namespace hp
