// Shared by GLSL and C++: the graphics passes (head, strands, tonemap) and their per-frame block.
// Render strands are pulled from the interpolate pass's buffers (shaders/shared/strands.h); the
// head mesh from its own position/normal/index buffers. Camera-facing ribbons: each segment of a
// strand is a quad of 6 vertices (triangle list) or, in lines mode, 2 vertices (line list).
#ifndef HP_SHARED_RENDER_H
#define HP_SHARED_RENDER_H
#include "common.h"
#include "opacity.h"
#include "environment.h"

HP_BEGIN
// Set 0 of the strand and head pipelines.
HP_CONST(uint, RENDER_BINDING_FRAME, 0)       // RenderFrame (read-only storage buffer, std140)
HP_CONST(uint, RENDER_BINDING_MARSCHNER, 1)   // MarschnerParams (read-only storage buffer, std140; shaders/shared/marschner.h)
HP_CONST(uint, RENDER_BINDING_LUT_M, 2)       // sampler2D
HP_CONST(uint, RENDER_BINDING_LUT_N0, 3)      // sampler2D
HP_CONST(uint, RENDER_BINDING_LUT_N1, 4)      // sampler2D
HP_CONST(uint, RENDER_BINDING_OPACITY, 5)     // sampler2DArray: per shadow slot 4 layers x RGBA = 16 opacity slices + 1 (shared/opacity.h)
HP_CONST(uint, RENDER_BINDING_LIGHT, 6)       // storage LightSpace[slots] (shared/opacity.h), written on the device by the bounds pass
HP_CONST(uint, RENDER_BINDING_POSITIONS, 7)   // strands: vec4[S*Q]; head: vec4 positions
HP_CONST(uint, RENDER_BINDING_TANGENTS, 8)    // strands: vec4[S*Q]; head: vec4 normals
HP_CONST(uint, RENDER_BINDING_ATTRIBUTES, 9)  // strands: StrandAttributes[S]; head: uint indices
HP_CONST(uint, RENDER_BINDING_HEAD_SHADOW, 10)  // sampler2DArrayShadow: the heads' depth map, a layer per slot (head_shadow.glsl)
// The head bounce map (head_bounce.glsl), numbered after the compute raster's own bindings
// (shared/raster.h, 11-25), which share that raster's set.
HP_CONST(uint, RENDER_BINDING_BOUNCE_FLUX, 26)      // sampler2D: flux, a = 1 + the hair's opacity (0: no skin)
HP_CONST(uint, RENDER_BINDING_BOUNCE_POSITION, 27)  // sampler2D: positions, w = the encoded normal
// The skin's bounce sampled along each strand (strand_bounce.comp writes, bounce_samples.glsl reads): per
// chunk uvec2[strands x samples], rgb as half floats (packHalf2x16: rg, then b and 0). After the raster's 32.
HP_CONST(uint, RENDER_BINDING_BOUNCE_SAMPLES, 33)
// strand_bounce.comp's blend step: the bounce gathered along the smoothed guides (uvec2[G x samples]), and
// the interpolation topology (shared/strands.h: StrandBindingGpu[chunk strands], uvec4[T] guide triangles).
HP_CONST(uint, RENDER_BINDING_BOUNCE_GUIDE_SAMPLES, 34)
HP_CONST(uint, RENDER_BINDING_STRAND_BINDINGS, 35)
HP_CONST(uint, RENDER_BINDING_SCALP_TRIANGLES, 36)
// The head's indirect light (head.vert; engine/core/hair/skin_transfer.h), float[vertices x SKIN_TRANSFER_FLOATS]
// (head.vert reads it as vec4s): per vertex the 9 SH coefficients of what the head hides of its lobe
// (SkinTransfer::occluded), the bounce transfer's 9 (per unit albedo), the share of its hemisphere covered by
// skin that passes light on (SkinTransfer::reflecting), and 0.
HP_CONST(uint, RENDER_BINDING_SKIN_TRANSFER, 37)
HP_CONST(uint, SKIN_TRANSFER_FLOATS, 20)
HP_CONST(uint, SKIN_TRANSFER_BOUNCE, 9)
HP_CONST(uint, SKIN_TRANSFER_REFLECTING, 18)
// strand_bounce.comp's steps (a specialization constant): gather at the points of the bound positions'
// strands, or blend each render strand's samples from its three guides' with its barycentrics.
HP_CONST(uint, BOUNCE_STEP_GATHER, 0)
HP_CONST(uint, BOUNCE_STEP_BLEND, 1)
// The tonemap pass reads the resolved HDR image.
HP_CONST(uint, TONEMAP_BINDING_HDR, 0)

// The fraction of a uniform sky that the fibres the camera sees receive, on average, from a head of hair
// (the ambient term's occlusion): a fibre at optical depth x below the surface of an optically thick
// layer sees (1/2) E_2(x) of the sky (E_2 the exponential integral: the outer hemisphere through the
// hair), and the camera sees depths with density exp(-x), so the mean is (1/2) int exp(-x) E_2(x) dx
// = (1 - ln 2) / 2. docs/SHADING.md "Ambient" compares it with the path-traced reference's sky.
HP_CONST(float, RENDER_HAIR_SKY_VISIBILITY, 0.15342641f)

// RenderFrame.options.z: single scattering, or with dual scattering's global forward part (physical
// fibre model only; hair_shading.glsl, docs/SHADING.md "Multiple scattering").
HP_CONST(uint, RENDER_SCATTERING_SINGLE, 0u)
HP_CONST(uint, RENDER_SCATTERING_DUAL, 1u)

// The head bounce map (compute/shadows/head_bounce_map.h, shaders/head_bounce.glsl): the skin seen from the
// light, texels per side (framed like the head's depth map), and the gather's pattern around the point's
// texel: RINGS rings of SPOKES samples, ring j at radius RADIUS x ((j + 1/2) / RINGS)^2 texels.
HP_CONST(uint, RENDER_BOUNCE_RESOLUTION, 128)
HP_CONST(uint, RENDER_BOUNCE_RINGS, 6)
HP_CONST(uint, RENDER_BOUNCE_SPOKES, 8)
HP_CONST(float, RENDER_BOUNCE_RADIUS, 40.0f)
// The gather runs at a few points along each strand, evenly spaced in its vertices (the first at the root,
// the last at the tip), and the shading interpolates between them (compute/strands/strand_buffers.h
// StrandOptions::bounceSamples: this default, or every vertex). docs/SHADING.md "Skin bounce" measures it.
HP_CONST(uint, RENDER_BOUNCE_STRAND_SAMPLES, 8)
HP_CONST(uint, RENDER_BOUNCE_WORKGROUP_SIZE, 64)

// Lights per frame (RenderFrame::lights); the first OPACITY_MAX_LIGHTS shadowed ones have shadow slots.
HP_CONST(uint, RENDER_MAX_LIGHTS, 8)
// FrameLight::position.w: the kind of light.
HP_CONST(float, RENDER_LIGHT_DIRECTIONAL, 0.0f)
HP_CONST(float, RENDER_LIGHT_SPOT, 1.0f)
HP_CONST(float, RENDER_LIGHT_POINT, 2.0f)

HP_CONST(uint, STRAND_VERTICES_PER_QUAD, 6)
HP_CONST(uint, STRAND_VERTICES_PER_LINE, 2)

// One light of a frame (hp::LightSpec: compute/raster/frame_block.h fills it; shared/light.h reads it).
struct FrameLight {
  vec4 direction;  // xyz unit, from the hair toward the light (spot: minus its axis; point: unused);
                   // w = the light's shadow slot (shared/opacity.h), -1: it casts no hair shadow
  vec4 radiance;   // rgb linear radiance (colour x intensity), w = 0
  vec4 position;   // xyz world position (spot, point); w = RENDER_LIGHT_*
  vec4 spot;       // spot: x = cos(cone half-angle), y = cos(inner angle, full radiance inside); spot and
                   // point: z = range of the inverse-square falloff (0: none); w = 0
};

// The heads' depth map of one shadow slot (layer `slot` of the map; compute/shadows/head_shadow_view.h).
struct FrameShadow {
  mat4 headViewProj;  // world -> clip of the slot's head depth map
  vec4 head;          // x = 1: the heads occlude this light (0: no map), y = receiver offset toward the
                      // light (scene units), z = 1 / map resolution (the shaders read the size from the
                      // map itself), w = one texel in scene units (at the heads' centre for a spot; the
                      // slope term of skin facing away from the light, head_shadow.glsl)
};

struct RenderFrame {
  mat4 view;
  mat4 proj;
  vec4 cameraPosition;   // xyz world; w = world size of one pixel at unit view depth
  vec4 hairColor;        // rgb exp(-2 sigma_a) (the scalp's tint); w = 0
  vec4 skinColor;        // rgb albedo of the head; w = wrap in [0, 1]
  vec4 strand;           // x = width at the root (scene units), y = width at the tip / root, z = shadow k
                         // (T = exp(-k alpha)), w = shadow bias in slices (lookups move this far toward the light)
  uvec4 options;         // x = vertices per strand Q, y = 1 when opacity shadows are on,
                         // z = RENDER_SCATTERING_*, w = 1 for deep opacity maps (OpacitySettings::deep)
  uvec4 lightCount;      // x = the lights in `lights`, y = the one in shadow slot 0 (the skin bounce's light;
                         // RENDER_MAX_LIGHTS: no slot 0), z = w = 0
  vec4 headBounce;       // x = 1: the hair adds the light the skin reflects (head_bounce.glsl) of light
                         // lightCount.y, y = the bounce map's texel size at the heads (scene units), z = the
                         // bounce's samples per strand (RENDER_BINDING_BOUNCE_SAMPLES), w = 1: the compute
                         // raster's far-side sky follows the depth behind the hair (LookSettings::farSideFromDepth)
  FrameLight lights[RENDER_MAX_LIGHTS];
  FrameShadow shadows[OPACITY_MAX_LIGHTS];  // per shadow slot
  mat4 previousViewProj;  // the previous frame's unjittered proj * view (motion vectors; shared/raster.h)
  vec4 jitter;            // xy = this view's subpixel jitter in pixels (x right, y down), already in `proj`; z = w = 0
  vec4 hairForward;       // with dual scattering on the physical model: rgb = the hair's mean forward albedo
                          // (MarschnerParams.forwardMean), w = the forward density d_f; else 0: what the light
                          // to and from the skin keeps through the hair (frame_shadows.glsl hairTransmittance)
  vec4 environment[ENV_SH_COEFFICIENTS];  // rgb = the environment's radiance SH convolved with the clamped
                                          // cosine over pi (shared/environment.h), the uniform ambient in
                                          // the first; w = 0
  vec4 skinSky[ENV_SH_COEFFICIENTS];     // the head's indirect light (LookSettings::skinIndirect): rgb = the sky's
                                         // radiance SH (environment and ambient) in the head's own axes; w of the
                                         // first = 1 when on (else head.frag takes `environment` on all skin)
  vec4 skinLights[ENV_SH_COEFFICIENTS];  // rgb = the lights' radiance SH in the head's axes, as they arrive at its
                                         // centre: what its skin passes on to itself; w = 0
};

struct StrandDrawPush {
  uint firstStrand;      // global index of the chunk's first strand (for per-strand variation)
  uint lines;            // 1: line list, 2 vertices per segment
  uint samples;          // samples per pixel of the attachments (coverage becomes a sample mask when > 1)
  uint pad0;
};

// strand_bounce.comp, per chunk: one invocation per sample.
struct StrandBouncePush {
  uint strandCount;  // strands sampled: the chunk's (all of them), or the guides (gather at the guides)
  uint vertices;     // Q
  uint samples;      // samples per strand (StrandLayout::bounceSamples)
  uint pad0;
};

struct TonemapPush {
  float exposure;
  float pad0;
  float pad1;
  float pad2;
};
HP_END

#ifdef __cplusplus
#include <cstddef>
static_assert(offsetof(hp::gpu::RenderFrame, cameraPosition) == 128);
static_assert(offsetof(hp::gpu::RenderFrame, options) == 192);
static_assert(offsetof(hp::gpu::RenderFrame, lights) == 240);
static_assert(offsetof(hp::gpu::RenderFrame, shadows) == 752);
static_assert(offsetof(hp::gpu::RenderFrame, previousViewProj) == 1072);
static_assert(offsetof(hp::gpu::RenderFrame, hairForward) == 1152);
static_assert(offsetof(hp::gpu::RenderFrame, environment) == 1168);
static_assert(offsetof(hp::gpu::RenderFrame, skinSky) == 1312);
static_assert(offsetof(hp::gpu::RenderFrame, skinLights) == 1456);
static_assert(sizeof(hp::gpu::RenderFrame) == 1600);
static_assert(sizeof(hp::gpu::FrameLight) == 64);
static_assert(sizeof(hp::gpu::FrameShadow) == 80);
static_assert(sizeof(hp::gpu::StrandBouncePush) == 16);
static_assert(sizeof(hp::gpu::StrandDrawPush) == 16);
static_assert(sizeof(hp::gpu::TonemapPush) == 16);
#endif
#endif
