#pragma once
// Contract: the shading bindings of one compute raster source (shaders/shared/render.h): its frame block
// and Marschner parameters as STORAGE buffers (the raster shaders read no uniform blocks), its material's
// LUTs, the opacity maps, LightSpace and the heads' depth shadow map (the skin's bounce comes with the
// strands: StrandChunk::bounce).
// What a compute::ShadingWriter writes for a head (compute/renderer/compute_raster.cpp) and for a test rig.
#include "hairpipe_volk.h"

#include "compute/raster/marschner_textures.h"
#include "compute/shadows/shadow_inputs.h"
#include "engine/vk/descriptors.h"

namespace hp::compute {
void writeRasterShading(const vk::DescriptorSet& set, VkBuffer frameBlock, const render::MarschnerTextures& marschner,
                        const render::ShadowInputs& shadows);
}  // namespace hp::compute
