#pragma once
// Contract: the values an application sets on hairpipe, each defined here once: the renderer's
// attachments and shadow maps, each instance's material, look, simulation and scalp input, the frame's
// light, view and head motion, and the colliders. Plain data with the defaults of hairpipe's own tools;
// nothing here is checked until a call takes it (that call returns the failure, naming the field).
// Units: scene units (metres for the default head), seconds, radians unless a name says degrees.
#include <vulkan/vulkan_core.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "hairpipe/math.h"
#include "hairpipe/result.h"

namespace hairpipe {
// How hair reaches the camera. Graphics: ribbons drawn by Renderer::recordDraw inside the application's
// rendering (MSAA). Compute: a tile rasterizer with analytic coverage and front-to-back transparency
// (Renderer::setRasterTarget, recordRaster, recordComposite). Auto: the one measured faster on the
// device's type (Compute on every device measured so far).
enum class RasterMode { Auto, Compute, Graphics };
// The fibre scattering function: Physical (an energy-conserving fibre with dual scattering), Float and
// Paper (Marschner's lookup textures at float and the paper's 8-bit precision), Direct (no textures).
enum class FibreModel { Direct, Paper, Float, Physical };
enum class Scattering { Single, Dual };
// How strands reach the opacity maps (Auto: Compute where its bins fit the device's storage limits).
enum class OpacityRaster { Auto, Compute, Graphics };

struct AttachmentFormats {  // the application's attachments recordDraw / recordComposite draw into
  VkFormat color = VK_FORMAT_R16G16B16A16_SFLOAT;  // its one colour attachment: blendable
  VkFormat depth = VK_FORMAT_D32_SFLOAT;           // D16, D32, or a combined D16S8, D24S8 or D32S8
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT;  // of both: 1, 2, 4, 8 or 16
  // Its stencil attachment: VK_FORMAT_UNDEFINED where the rendering has none (a combined depth attached as
  // depth only), else the depth's own combined format (the same image view as depth and stencil).
  VkFormat stencil = VK_FORMAT_UNDEFINED;
  // The depth's convention. false: cleared to 1, nearer is smaller (hairpipe tests LESS_OR_EQUAL); true:
  // reversed-Z, cleared to 0, nearer is larger (GREATER_OR_EQUAL), and each View::projection maps the near
  // plane to 1 (Camera::reversedDepth makes one; a far plane at infinity is fine).
  bool reversedDepth = false;
  // The rendering's further colour attachments after `color`, in attachment order (locations 1, 2, ...: an
  // engine's velocity or normal target in its main pass), each a colour format or VK_FORMAT_UNDEFINED for a slot
  // the rendering leaves unused (a null image view there), at most 7 and together with `color` at most the
  // device's maxColorAttachments. hairpipe's draws leave them as they are (colour write mask 0), so its
  // pipelines match a pass that renders into them too, except that recordComposite writes the attachment
  // RendererSettings::velocityOutput names. With any, the device must have the
  // independentBlend feature enabled (a headless Context enables it where the device has it).
  std::vector<VkFormat> otherColors;
};

// The hair's motion written by recordComposite into the application's own velocity target, one of
// AttachmentFormats::otherColors (compute raster with RendererSettings::motionVectors): where the hair covers a
// pixel by more than minCoverage its motion replaces what the attachment holds there; elsewhere the attachment
// is left as it is. The engine's temporal passes then see the hair move without a pass of their own.
struct VelocityOutput {
  // Index into otherColors (a float, UNORM or SNORM format: not UNDEFINED, SRGB or integer); -1: none (default).
  int attachment = -1;
  // Written per pixel into the attachment's first two channels (the others keep theirs): motion.x * scaleX +
  // offsetX and motion.y * scaleY + offsetY, motion being Renderer::motionImage's (pixels, this frame's
  // unjittered position minus the previous frame's, x right, y down). For example scaleX = 1 / width,
  // scaleY = -1 / height for UV units with y up; negative scales for previous minus current; an offset of 0.5
  // for a UNORM target. Finite; the format clamps or rounds what it cannot hold.
  float scaleX = 1.0f, scaleY = 1.0f;
  float offsetX = 0.0f, offsetY = 0.0f;
  // [0, 1): the hair's coverage of the pixel (the alpha recordComposite leaves there; over several samples,
  // their mean) must exceed it. Every sample of such a pixel takes the motion.
  float minCoverage = 0.5f;
};

// The opacity shadow maps the Renderer shares among its instances (one light).
struct OpacitySettings {
  bool enabled = true;
  std::uint32_t resolution = 512;   // texels per side, [16, 4096]
  bool footprint = true;            // strands add their projected area per texel (else strandOpacity)
  float strandOpacity = 0.04f;      // (0, 100], when footprint is off
  float headOpacity = 0.0f;         // heads also drawn into the slices with this opacity, [0, 1e4]
  std::uint32_t headShadowResolution = 1024;  // the heads' depth shadow map, [16, 8192]
  float k = 1.0f;                   // transmittance exp(-k alpha), [0, 1e3]
  float biasSlices = 1.0f;          // global slices: lookup bias toward the light, [0, 16]
  float deepBiasSlices = 0.25f;     // deep slices: lookup bias toward the light, [0, 16]
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;  // or VK_FORMAT_R16G16B16A16_SFLOAT
  OpacityRaster raster = OpacityRaster::Auto;
  bool deep = true;                 // deep opacity maps (compute opacity path)
  // Render strands per head drawn into the opacity maps at most; 0 (the default): all. Past it the maps take
  // an even sample, the first shadowStrands strands (an order whose every prefix thins each scalp triangle
  // alike), each widened by strands / shadowStrands so the maps keep the hair's opacity, as the level of
  // detail does. The maps' cost follows the strands drawn; the sample's shadow is lighter where few strands
  // cast it (at 136,320 strands with 65,536 drawn, the skin along the hair's edge on the face shows a lit
  // sliver: docs/PERFORMANCE.md "Opacity maps"). With the level of detail, the smaller of the two.
  std::uint32_t shadowStrands = 0;
};

struct RendererSettings {
  AttachmentFormats formats;
  OpacitySettings opacity;
  std::uint32_t framesInFlight = 2;    // [1, 8]
  std::uint32_t maxViewsPerFrame = 4;  // [1, 16]: recordDraw calls of one frame with different cameras
  // How many of a frame's lights cast hair shadows, [1, 4] (the first that ask for shadows, in order; the
  // rest shade unshadowed). Each costs its own opacity maps, resolution^2 x 5 texels of the opacity format
  // (20 MiB at the default 512 RGBA32F), a layer of the heads' depth map (4 MiB at 1024) and its shadow
  // passes per frame.
  std::uint32_t shadowedLights = 1;
  // Motion vectors for temporal anti-aliasing (compute raster only: with the graphics raster create fails):
  // each instance keeps its previous render
  // positions (one copy of them per recordUpdate) and the raster target writes the hair's screen motion
  // (Renderer::motionImage). The graphics raster writes none.
  bool motionVectors = false;
  // recordComposite also writes the hair's motion into the application's velocity target (needs
  // motionVectors and the compute raster; see VelocityOutput).
  VelocityOutput velocityOutput;
  // The application's occluders shadow the hair (Renderer::occluderTargets): it draws its own character's depth
  // into the heads' depth shadow map after recordShadows. Instances without hairpipe's head (drawHead false,
  // or an asset without a head mesh) then frame that map around their guides, so it exists for them too: a
  // depth pass per shadowed light, and the skin-bounce passes of a look with skinBounce, which gather nothing
  // from a head that is not drawn.
  bool applicationOccluders = false;
  RasterMode raster = RasterMode::Graphics;
  std::uint32_t tileBudget = 16384;    // compute raster: list entries kept per 8x8 tile, [1, 2^24]
  // Compute raster: the tile lists (most of a raster target's device memory) start at 2 entries per strand
  // segment plus 16 per tile and grow, to twice a frame's need, once a frame's views ask for more than 3/4 of
  // them (known framesInFlight frames later, when that frame is complete), up to what growRasterLists = false
  // reserves from the start: 8 per segment plus 16 per tile, enough for close-ups. Until they have grown,
  // after a camera cut to a view that asks for more than they hold (a close-up) framesInFlight frames are
  // drawn with full lists: every tile's farthest entries thinned alike (its nearest kept), as ever when full.
  // A target the Renderer rebuilds (a density change, another extent) starts at the size per segment it had
  // grown to. Grown lists shrink back, to twice the most those frames asked (at least 1 per segment plus 16
  // per tile), after rasterListShrinkFrames frames in a row that each asked for under 1/4 of them; 0 keeps
  // them at their largest (no reallocation after a close-up).
  bool growRasterLists = false;
  std::uint32_t rasterListShrinkFrames = 300;  // 5 s at 60 Hz
  // Compute raster: where a render strand's vertices 2j and 2j + 2 lie within this many pixels of each other on
  // screen (and the strand turns there by at most ~28 degrees on screen), the odd vertex between them is not
  // shaded and takes their mean radiance, [0, 4096]; 0 shades every vertex. Shading is most of the hair's
  // cost per vertex, and at the default framing a strand's segments are a few pixels long
  // (docs/PERFORMANCE.md "Shading spacing": the image and the time).
  float shadingSpacing = 24.0f;
  // The data of an earlier run's Renderer::pipelineCacheData(): every pipeline is built through a
  // VkPipelineCache started from it. Data of another device or driver is ignored (as drivers do); data too
  // short for a pipeline cache header, or whose header size disagrees with it, is refused.
  std::vector<std::uint8_t> pipelineCache;
};

// The fibre's optics (Marschner et al. 2003; d'Eon et al. 2011 for the physical model).
struct Material {
  double eta = 1.55;                                   // index of refraction
  std::array<double, 3> absorption = {0.55, 0.91, 1.78};  // sigma_a per unit radius, RGB (brown)
  double alphaR = -0.13089969389957470;                // R lobe's longitudinal shift (-7.5 degrees)
  double betaR = 0.13089969389957470;                  // R lobe's longitudinal width (7.5 degrees)
  double kG = 0.5;                                     // caustic glint scale
  double wc = 0.26179938779914941;                     // caustic azimuthal width (15 degrees)
  double dEta = 0.3;                                   // caustic fade range for eta'
  double dhM = 0.5;                                    // caustic maximum h range
  double betaN = 0.17453292519943295;                  // azimuthal width, physical model (10 degrees)
  // Each strand's alphaR is offset by a value uniform in [-tiltVariation, tiltVariation) from its own hash,
  // [0, 10 degrees] (physical and direct shading; the paper and float lookup modes ignore it).
  double tiltVariation = 0.034906585039886591;         // 2 degrees
  // Each strand's betaR is scaled by one of 7 levels evenly spaced over [1 - roughnessVariation,
  // 1 + roughnessVariation], picked by its own hash; 0 or [0.01, 0.25] (physical and direct shading; the paper and float
  // lookup modes ignore it).
  double roughnessVariation = 0.15;
};
// The absorption that gives a fibre this colour of its forward-scattering highlight: each linear RGB
// channel, in (0, 1], is what survives one pass through the fibre's centre (docs/THEORY.md).
Result<std::array<double, 3>> absorptionFromColor(float r, float g, float b) noexcept;

struct LookSettings {
  float strandWidth = 0.0005f;       // ribbon width at the root (a render strand stands for a clump)
  float tipWidthFraction = 0.35f;    // width at the tip relative to the root, [0, 1]
  Vec3 skinColor{0.62f, 0.45f, 0.36f};  // the head's albedo, linear RGB in [0, 1]
  float wrap = 0.0f;                 // the head's wrap lighting, [0, 1]; 0: Lambertian (as the path-traced reference)
  float ambient = 0.06f;             // uniform sky radiance, added to `environment`
  // The environment's radiance (what environmentLighting leaves for the ambient term) as 9 RGB spherical-
  // harmonic coefficients of order <= 2 in world axes (the basis of docs/SHADING.md "Environment"); all zero:
  // none. It lights the hair and the head like the uniform sky, by direction.
  std::array<Vec3, 9> environment{};
  Scattering scattering = Scattering::Dual;  // Dual: physical model only
  bool skinBounce = true;            // sunlight the skin reflects onto the hair
  // The head's indirect light: the sky it sees past its own shape (a jaw over the throat) and the light its skin
  // passes on to itself, from a transfer computed per vertex when the head is loaded; false: the whole sky on
  // every point of skin and no light between its parts (docs/SHADING.md "The skin's indirect light").
  bool skinIndirect = true;
  // Compute raster: where the depth the hair is composited over (the character's, or the engine's) lies behind
  // a hair vertex, the sky on the fibre's far side is the light the hair beneath passes on; false: open sky.
  bool farSideFromDepth = true;
};

struct SimulationSettings {
  double dt = 1.0 / 60.0;                 // frame time step (s)
  std::uint32_t substeps = 2;             // Verlet substeps per frame
  std::uint32_t iterations = 8;           // constraint + collision iterations per substep
  std::array<double, 3> gravity = {0.0, -9.81, 0.0};  // world space
  double damping = 0.02;                  // fraction of velocity removed per substep, [0, 1]
  double pearlRadius = 0.002;             // sphere around every particle
  double stiffness = 0.05;                // shape stiffness toward the rest pose at the root, [0, 1]
  double stiffnessFalloff = 0.7;          // its per-segment decay toward the tip, [0, 1]
  // Each segment's pull toward its rest-pose bend relative to its parent segment (keeps waves and curls
  // under gravity and motion), [0, 0.9]; 0: off.
  double localStiffness = 0.0;
  double maxSpeed = 10.0;                 // particle speed clamp, > 0
  // Strand interaction through a density / velocity grid around the instance, rebuilt every frame (acts when
  // volume or friction is above 0). volume: how fast hair flows out of places denser than volumeTarget (in
  // units of the rest pose's mean density), in grid cells a frame per unit of density change over a cell,
  // [0, 10] and [0.01, 100]; friction: fraction of each
  // particle's velocity pulled toward the hair's around it per substep, [0, 1]; gridResolution: cells along
  // the grid's longest side, [4, 128], fixed when the instance is created.
  // Off by default (0, 0); volume 0.6 and friction 0.1 give the default head a body (docs/THEORY.md §2.7).
  double volume = 0.0;
  double volumeTarget = 0.5;
  double friction = 0.0;
  std::uint32_t gridResolution = 32;
  std::array<double, 3> windDirection = {1.0, 0.0, 0.0};
  double windStrength = 0.0;              // acceleration along windDirection
  double windGust = 0.0;                  // relative gust amplitude, [0, 1]
  double windGustFrequency = 0.5;         // Hz
};

// Up to four bones and their weights (>= 0, summing to 1) for one guide's root.
struct SkinWeights {
  std::array<std::uint32_t, 4> bones{};
  std::array<float, 4> weights{1.0f, 0.0f, 0.0f, 0.0f};
};

// The skinning of `guideCount` guides (Asset::guideCount()) from a TressFX .tfxbone file: per guide its bones
// (positions in the file's bone list, whose names the application maps to its joints) and weights
// normalised to sum 1; guides past the file's strands take its last strand's. Bad files, and files with more
// strands than guides, fail naming the file and the problem. For ScalpInput::skin (Kind::Bones).
struct TfxBoneSkinning {
  std::vector<std::string> boneNames;
  std::vector<SkinWeights> skin;
};
Result<TfxBoneSkinning> loadTfxBoneSkinning(const std::string& path, std::uint32_t guideCount) noexcept;

class Asset;
// The skinning of an asset's guides from its skinned character mesh (AssetSource::mesh: a glTF skin or a
// .tfxmesh's weights): each root takes the weights of the triangle it is bound to, blended by its
// barycentric coordinates (the four heaviest joints, normalised), as a TressFX exporter weights a strand by
// the mesh where it grows. A root then moves exactly with a rigidly weighted region, and with a blended one
// as linear blend skinning of the root itself (within the triangle's own blending error). boneNames: the
// mesh's joints; bones index them. For ScalpInput::skin (Kind::Bones). Fails without a skinned mesh.
struct MeshSkinning {
  std::vector<std::string> boneNames;
  std::vector<SkinWeights> skin;
};
Result<MeshSkinning> meshSkinning(const Asset& asset) noexcept;
// The skinned mesh's bones posed by its animation clip `clip` at `seconds` (clamped to the clip): per bone
// the head-space matrix from the bind pose to the pose (the identity for every bone in the rest pose when the
// mesh's bind pose is its rest pose, as exporters usually write it). Instance::setBones
// takes headToWorld times each. Fails naming the clips there are when none is called `clip`.
Result<std::vector<Mat4>> meshClipPose(const Asset& asset, const std::string& clip, float seconds) noexcept;

// Where the guides' roots come from each frame.
struct ScalpInput {
  enum class Kind {
    Rigid,       // the head motion (Instance::setMotion) carries the roots
    RootFrames,  // the application's skinning writes root frames into its own buffer
    Bones        // hairpipe skins the roots with skin[] and the bone matrices of Instance::setBones
  };
  Kind kind = Kind::Rigid;
  // RootFrames: the application's buffer (VK_BUFFER_USAGE_STORAGE_BUFFER_BIT), at least guides x 32 bytes:
  // per guide the root's world position (vec4, w unused) and its unit orientation quaternion (x, y, z, w).
  // The application's writes are made visible to COMPUTE_SHADER storage reads before recordUpdate,
  // which only reads it, in COMPUTE_SHADER.
  // The frames may start at rootFramesOffset (a sub-allocation of a larger buffer): a multiple of the
  // device's minStorageBufferOffsetAlignment, with rootFramesBytes counted from there.
  VkBuffer rootFrames = VK_NULL_HANDLE;
  VkDeviceSize rootFramesBytes = 0;
  VkDeviceSize rootFramesOffset = 0;
  std::vector<SkinWeights> skin;    // Bones: one per guide
  std::uint32_t boneCount = 0;      // Bones: [1, 256]
};

// Level of detail by distance. Per view, from the distance d between its eye and the instance's head
// origin: fraction 1 up to startDistance, falling linearly to minFraction at endDistance and beyond. The
// instance then draws that fraction of its render strands (an even thinning: every scalp triangle keeps
// its share) and widens each by 1 / fraction, so the hair keeps its coverage. The shadow maps use the
// largest fraction of the views most recently drawn. Changing it needs no rebuild.
struct LodSettings {
  bool enabled = false;
  float startDistance = 1.5f;  // scene units, >= 0
  float endDistance = 6.0f;    // > startDistance
  float minFraction = 0.25f;   // [0.001, 1]
};

// Groom detail added to each render strand at interpolation, deterministic per strand (the same shape in
// every frame and run): clumping toward clump centres hashed in each scalp triangle, curl around the clumped
// centreline, frizz. Lengths are scene units; v runs from 0 at the root to 1 at the tip; curl and frizz ramp
// in over the first 15% of v. The defaults were chosen by looking at the default head, in metres (docs/THEORY.md
// "Groom detail"): four clumps a triangle, a gentle wave, a little frizz that grows toward the hairline.
// GroomSettings::none() adds nothing (each strand the plain blend of its three guides).
struct GroomSettings {
  std::uint32_t clumpsPerTriangle = 4;  // [0, 64]; 0: no clumping
  float clumpStrength = 0.4f;           // pull toward the clump centre at the tip, [0, 1]
  float clumpShape = 1.5f;              // the pull is clumpStrength x v^clumpShape, [0.1, 10]
  float curlRadius = 0.004f;            // helix radius, [0, 1]; 0: no curl
  float curlTurns = 5.0f;               // turns per unit of strand length, [0, 10000]
  float curlVariation = 0.5f;           // per-strand spread of radius and turns, [0, 1]
  float frizzAmplitude = 0.0008f;       // at the tip (growing as v^2), [0, 1]; 0: no frizz
  float frizzFrequency = 40.0f;         // noise cycles per unit of length, (0, 10000]
  // Frizz by region: the amplitude times 1 + frizzHairline x exp(-d / frizzHairlineWidth), d the distance
  // of the strand's scalp triangle from the hairline (the scalp's open edge), [0, 100]; 0: the same everywhere.
  float frizzHairline = 4.0f;
  float frizzHairlineWidth = 0.02f;     // units of length, (0, 10]

  // No clumps, curl or frizz: every render strand the plain blend of its guides.
  static constexpr GroomSettings none() {
    GroomSettings g;
    g.clumpsPerTriangle = 0;
    g.clumpStrength = 0.0f;
    g.clumpShape = 1.0f;
    g.curlRadius = 0.0f;
    g.curlTurns = 0.0f;
    g.curlVariation = 0.0f;
    g.frizzAmplitude = 0.0f;
    g.frizzHairline = 0.0f;
    return g;
  }
};

struct InstanceSettings {
  SimulationSettings simulation;
  Material material;
  FibreModel fibre = FibreModel::Physical;
  LookSettings look;
  ScalpInput scalp;
  std::uint32_t verticesPerStrand = 36;  // render strand vertices, [guide particles, 256]
  bool guidesOnly = false;               // debug: draw the smoothed guides instead of dense strands
  // false: hair only. The asset's proxy head is not drawn (recordDraw draws this instance's hair alone,
  // depth-tested against what the application drew before it; the compute rasterizer tests against the
  // depth image it is given), casts no shadow (neither in the opacity maps nor in the heads' depth map)
  // and bounces no light onto the hair (the look's skinBounce has no skin to bounce from). Collisions are
  // unchanged: they come from the asset's colliders and distance field, never from what is drawn.
  bool drawHead = true;
  LodSettings lod;
  GroomSettings groom;
  // Points along each strand where the skin's bounce light is gathered once a frame; the shading
  // interpolates between them. [2, 256]; verticesPerStrand or more gathers at every vertex.
  std::uint32_t skinBounceSamples = 8;
  // true: the skin's bounce is gathered along the guides and blended into each render strand (2,130 gathers on
  // the default head instead of one per render strand; within 3% of the gather along every strand,
  // docs/SHADING.md "Skin bounce"); false: gathered along every render strand.
  bool skinBounceAtGuides = true;
};

// One light of a frame. direction: unit, from the lit hair toward the light (a spot's: minus its axis; a
// point light's is unused but must still be a unit vector). A frame takes up to 8 lights; those with
// `shadows` cast hair shadows (opacity maps, and the heads' depth map) while the Renderer has shadow slots
// (RendererSettings::shadowedLights), the others light unshadowed. The skin's bounce light comes from the
// first shadowed light only. A spot shines along -direction from `position` with a cone of half-angle
// coneDeg (the last 20% fades out). A point light's shadows are drawn as a spot aimed at the heads with an
// 80-degree half-angle: hair outside that cone (a point light among the hair) is lit unshadowed.
struct Light {
  enum class Type { Directional, Spot, Point };
  Type type = Type::Directional;
  Vec3 direction{0.4472136f, 0.7155418f, 0.5366563f};  // unit
  Vec3 color{1.0f, 1.0f, 1.0f};                        // linear RGB
  // intensity x the largest colour component in [0, 10000]: hairpipe's radiance images are half floats (scale
  // physical units down and the exposure up)
  float intensity = 3.0f;
  Vec3 position{};        // spot, point
  float coneDeg = 30.0f;  // spot: (0, 80]
  float range = 0.0f;     // spot, point: (range / distance)^2 falloff; 0 = none
  bool shadows = true;    // casts hair shadows while a shadow slot is left
};

// An environment light as an equirectangular image of linear RGB radiance: row 0 straight up (+y), the last row
// straight down, the middle column looking along +z; turned about +y by rotationDeg (counter-clockwise seen
// from above) and scaled by intensity.
struct EnvironmentImage {
  std::uint32_t width = 0, height = 0;  // at most 8192 x 4096 texels in all
  std::vector<Vec3> texels;             // width x height, row-major, finite, >= 0, x intensity <= 1e9
  double rotationDeg = 0.0;
  double intensity = 1.0;               // [0, 1000]
};

// What the renderer draws of an environment: its bright regions (up to maxLights, [0, 4]) as shadowed
// directional lights, to be added to the frame's lights, and the rest as LookSettings::environment (refused
// when a coefficient would exceed LookSettings' +-10000: more lights or a lower intensity then). The
// path-traced reference renders the image itself; docs/SHADING.md "Environment" has the split and its accuracy.
struct EnvironmentLighting {
  std::vector<Light> lights;         // brightest first
  std::array<Vec3, 9> harmonics{};   // for LookSettings::environment
};
Result<EnvironmentLighting> environmentLighting(const EnvironmentImage& image, std::uint32_t maxLights = 2) noexcept;
// The built-in studio: a dim room, a soft box to the front left, a rim light above and behind (256 x 128).
Result<EnvironmentImage> studioEnvironment() noexcept;

// One camera of a frame. view: world to view space (right-handed, looking down -Z); projection: view to
// clip space with depth in [0, 1] and y up (OpenGL-style, e.g. glm::perspectiveRH_ZO: hairpipe's draws
// flip y with a negative-height viewport over the whole extent). eye: the camera's world position; fovY
// the vertical field of view of `projection` (it sets the strands' pixel width). Several views of one
// frame (a mirror, a second camera) reuse its update and shadows; each needs its own index (recordDraw
// refuses a second view of the frame at an index another view took; the same view again passes).
struct View {
  Mat4 view;
  Mat4 projection;
  Vec3 eye;
  float fovY = 0.6f;             // vertical field of view of `projection` (radians)
  VkExtent2D extent{1, 1};
  std::uint32_t index = 0;       // [0, RendererSettings::maxViewsPerFrame)
  bool lines = false;            // debugging: strands as 1-pixel lines
  // Subpixel jitter for temporal anti-aliasing, in pixels (x right, y down), each in [-1, 1]: hairpipe
  // offsets `projection` by it for the heads and the hair (give it the unjittered projection). Motion
  // vectors leave it out.
  float jitterX = 0.0f, jitterY = 0.0f;
  // The previous frame's unjittered projection * view, for motion vectors (hasPrevious false: the camera
  // did not move).
  Mat4 previousViewProjection;
  bool hasPrevious = false;
};

// A camera in hairpipe's conventions (makeView turns it into a View): looking from eye at target,
// perspective with vertical field of view fovY and the clip planes nearZ/farZ (0 < nearZ < farZ).
struct Camera {
  Vec3 eye{0.0f, 0.0f, 1.0f};
  Vec3 target{};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float fovY = 0.6f;
  float nearZ = 0.01f;
  float farZ = 100.0f;
  bool reversedDepth = false;  // a reversed-Z projection (near plane at depth 1, far at 0)
};

// Where a head is during one frame (head space to world), and the clock.
struct HeadMotion {
  Mat4 from;                 // at the start of the frame
  Mat4 to;                   // at its end
  double time = 0.0;         // seconds at the start of the frame
  bool teleport = false;     // carry the hair rigidly instead of simulating the jump
};

// Colliders in head space, moving with the head.
struct SphereCollider {
  Vec3 center;
  float radius = 0.0f;
};
struct CapsuleCollider {  // the points within radius of the segment a-b
  Vec3 a, b;
  float radius = 0.0f;
};
}  // namespace hairpipe
