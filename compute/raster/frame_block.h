#pragma once
// Contract: fills the per-frame block the draw passes read (gpu::RenderFrame) from a camera, the frame's
// lights with their shadow slots and head map framings, the hair material, the look settings and the
// opacity shadow settings (on/off, k, bias). Pure host code.
#include "engine/core/hair/scene.h"
#include "compute/raster/camera.h"
#include "compute/shadows/frame_lights.h"
#include "compute/shadows/opacity_settings.h"
#include "compute/strands/strand_buffers.h"
#include "hairpipe/settings.h"
#include "hairpipe_volk.h"

#include <array>
#include <optional>
#include <string>

#include "shaders/shared/render.h"

namespace hp::render {
using Scattering = hairpipe::Scattering;  // defined once, in the public API
Scattering parseScattering(const std::string& text);  // "single", "dual"; else hp::Error
const char* scatteringName(Scattering s);              // the names parseScattering reads

struct LookSettings {
  // Ribbon width at the root (scene units). Real hair is 50-120 um, but a render strand stands for a
  // few hundred real ones (20k of them replace ~100k hairs), so it is drawn as a thin clump.
  float strandWidth = 0.0005f;
  float tipWidthFraction = 0.35f;    // width at the tip relative to the root
  glm::vec3 skinColor{0.62f, 0.45f, 0.36f};
  float wrap = 0.0f;                 // the paper's wrap term for the head, [0, 1]; 0: Lambertian (the indirect light
                                     // stands for what the wrap imitated: docs/SHADING.md "The skin's indirect light")
  float ambient = 0.06f;             // a uniform sky's radiance, added to `environment`
  // The environment's radiance as 9 RGB spherical-harmonic coefficients (engine/core/shading/environment_sh.h:
  // what splitEnvironment leaves after its lights, or projectEnvironment of a whole map); all zero: none. It lights the hair and the skin, occluded like
  // the uniform sky (docs/SHADING.md "Environment").
  std::array<glm::vec3, 9> environment{};
  // Dual (default): add the light the hair in front of a fibre scattered forward onto it and the light the
  // hair around it scattered back (physical fibre model only; the others draw single scattering either
  // way). docs/SHADING.md "Multiple scattering", "Local back-scattering".
  Scattering scattering = Scattering::Dual;
  // Add the sunlight the skin reflects onto the hair (one bounce from the head bounce map, both rasters;
  // needs the shadows on and a head, as the map is drawn with the head's depth shadow map and framed by
  // it). docs/SHADING.md "Skin bounce".
  bool skinBounce = true;
  // The head's indirect light from its transfer (engine/core/hair/skin_transfer.h): the sky past the head's
  // own shape and one bounce (with a geometric series for the rest) off its skin; false: the open sky on all
  // skin. docs/SHADING.md "The skin's indirect light".
  bool skinIndirect = true;
  // Compute raster: where the depth image it composites over (the head's, or the engine's) lies behind a hair
  // vertex, the sky on the fibre's far side is what the hair beneath passes on, not the open sky (docs/SHADING.md
  // "Ambient"). false: every far side open, as the graphics raster draws it.
  bool farSideFromDepth = true;
  void validate() const;             // throws hp::Error naming the field
};

// What the hair passes on forward to a diffuse receiver beneath it (RenderFrame::hairForward, the public
// hairpipeHairTransmittance's `forward`): the material's mean forward albedo and its weight with dual
// scattering, 0 with single.
glm::vec4 hairForward(const LookSettings& look, const glm::vec3& forwardAlbedo);

// The skin's bounce (headBounce) is on where the look asks for it and slot 0 has a head map (the bounce map
// is drawn from slot 0's light, framed like its head map). forwardAlbedo: the material's mean forward
// albedo (MarschnerParams.forwardMean; 0 for the paper's model), taken with dual scattering. `strands`: the
// vertices and bounce samples per strand of the instance's buffers.
gpu::RenderFrame makeRenderFrame(const CameraMatrices& camera, VkExtent2D extent, const FrameLights& lights,
                                 const HairMaterial& material, const LookSettings& look,
                                 const compute::StrandLayout& strands, const OpacitySettings& opacity,
                                 const glm::vec3& forwardAlbedo = glm::vec3(0.0f));
// The head's indirect light (LookSettings::skinIndirect): the sky's radiance SH (the look's environment and
// ambient) and the lights' (as they arrive at headCentre, world space: cone and distance included) turned into
// the head's own axes (headToWorld's rotation; its scale is divided out), what head.vert pairs with the head's
// transfer. Off: the flag cleared, head.frag takes the open sky.
void setSkinLight(gpu::RenderFrame& frame, const glm::mat4& headToWorld, const glm::vec3& headCentre,
                  const FrameLights& lights, const LookSettings& look);
// A view's subpixel jitter (pixels, x right, y down) moved into `frame.proj`, and the previous frame's
// unjittered proj * view for motion vectors (none: makeRenderFrame's, this frame's own: no camera motion).
void setViewMotion(gpu::RenderFrame& frame, VkExtent2D extent, const glm::vec2& jitter,
                   const std::optional<glm::mat4>& previousViewProj);
}  // namespace hp::render
