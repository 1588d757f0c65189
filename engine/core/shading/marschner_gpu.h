#pragma once
// Contract: fills the GPU block gpu::MarschnerParams (shaders/shared/marschner.h) from a material and
// the LUT built for it, and pins that block's std140/std430 layout with static_asserts (8 + 4 x 32 + 1 vec4s,
// every member 16-byte aligned, identical in both layouts). The mode written into control.x is the
// LUT's mode; the scale vectors are the textures' per-channel factors (1 where unused); skyAlbedo is
// hp::skyAlbedo of the LUT's fibre model (the ambient term's albedo), skyAlbedoFront its part from the viewer's
// side (hp::skyAlbedoOver over [0, pi/2]); the multiple-scattering tables are
// hp::multipleScatteringTables for the physical mode and zero for the others.
#include <cstddef>

#include "engine/core/shading/lut.h"
#include "shaders/shared/marschner.h"

namespace hp {
static_assert(sizeof(gpu::MarschnerParams) == 160 + 4 * 16 * gpu::MARSCHNER_SPREAD_ENTRIES + 16);
static_assert(offsetof(gpu::MarschnerParams, skyAlbedoFront) == 160 + 4 * 16 * gpu::MARSCHNER_SPREAD_ENTRIES);
static_assert(offsetof(gpu::MarschnerParams, absorption) == 0);
static_assert(offsetof(gpu::MarschnerParams, longitudinal) == 16);
static_assert(offsetof(gpu::MarschnerParams, caustic) == 32);
static_assert(offsetof(gpu::MarschnerParams, mScale) == 48);
static_assert(offsetof(gpu::MarschnerParams, n0Scale) == 64);
static_assert(offsetof(gpu::MarschnerParams, n1Scale) == 80);
static_assert(offsetof(gpu::MarschnerParams, control) == 96);
static_assert(offsetof(gpu::MarschnerParams, skyAlbedo) == 112);
static_assert(offsetof(gpu::MarschnerParams, skyVisibility) == 128);
static_assert(offsetof(gpu::MarschnerParams, forwardMean) == 144);
static_assert(offsetof(gpu::MarschnerParams, forwardAlbedo) == 160);

std::uint32_t gpuModeOf(LutMode mode);
gpu::MarschnerParams marschnerGpuParams(const MarschnerLut& lut);
}  // namespace hp
