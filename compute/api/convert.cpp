#include "compute/api/convert.h"

#include <cstring>

#include "engine/core/hair/strand_topology.h"

namespace hairpipe::convert {
glm::vec3 vec(const Vec3& v) { return {v.x, v.y, v.z}; }
Vec3 vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 dvec(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }

glm::mat4 mat(const Mat4& m) {
  glm::mat4 out;
  static_assert(sizeof(out) == sizeof(m.m));
  std::memcpy(&out, m.m, sizeof(m.m));  // both column-major
  return out;
}

Mat4 mat(const glm::mat4& m) {
  Mat4 out;
  std::memcpy(out.m, &m, sizeof(out.m));
  return out;
}

hp::RasterMode raster(RasterMode mode) {
  switch (mode) {
    case RasterMode::Compute: return hp::RasterMode::Compute;
    case RasterMode::Graphics: return hp::RasterMode::Graphics;
    case RasterMode::Auto: break;
  }
  return hp::RasterMode::Auto;
}

RasterMode raster(hp::RasterMode mode) {
  switch (mode) {
    case hp::RasterMode::Compute: return RasterMode::Compute;
    case hp::RasterMode::Graphics: return RasterMode::Graphics;
    case hp::RasterMode::Auto: break;
  }
  return RasterMode::Auto;
}

hp::LutMode fibre(FibreModel model) {
  switch (model) {
    case FibreModel::Direct: return hp::LutMode::Direct;
    case FibreModel::Paper: return hp::LutMode::Paper;
    case FibreModel::Float: return hp::LutMode::Float;
    case FibreModel::Physical: break;
  }
  return hp::LutMode::Physical;
}

hp::RendererSettings renderer(const RendererSettings& s) {
  hp::RendererSettings r;
  r.formats = s.formats;
  r.opacity = s.opacity;
  r.framesInFlight = s.framesInFlight;
  r.maxViewsPerFrame = s.maxViewsPerFrame;
  r.shadowedLights = s.shadowedLights;
  r.motionVectors = s.motionVectors;
  r.velocityOutput = s.velocityOutput;
  r.applicationOccluders = s.applicationOccluders;
  r.raster = raster(s.raster);
  r.rasterSettings.tileBudget = s.tileBudget;
  r.rasterSettings.shadingSpacing = s.shadingSpacing;
  r.rasterSettings.growLists = s.growRasterLists;
  r.rasterSettings.listShrinkFrames = s.rasterListShrinkFrames;
  r.pipelineCache = s.pipelineCache;
  return r;
}

hp::HairMaterial material(const Material& m) {
  hp::HairMaterial h;
  h.eta = m.eta;
  h.absorption = dvec(m.absorption);
  h.alphaR = m.alphaR;
  h.betaR = m.betaR;
  h.kG = m.kG;
  h.wc = m.wc;
  h.dEta = m.dEta;
  h.dhM = m.dhM;
  h.betaN = m.betaN;
  h.tiltVariation = m.tiltVariation;
  h.roughnessVariation = m.roughnessVariation;
  return h;
}

hp::render::LookSettings look(const LookSettings& l) {
  hp::render::LookSettings h;
  h.strandWidth = l.strandWidth;
  h.tipWidthFraction = l.tipWidthFraction;
  h.skinColor = vec(l.skinColor);
  h.wrap = l.wrap;
  h.ambient = l.ambient;
  for (std::size_t i = 0; i < h.environment.size(); ++i) h.environment[i] = vec(l.environment[i]);
  h.scattering = l.scattering;
  h.skinBounce = l.skinBounce;
  h.skinIndirect = l.skinIndirect;
  h.farSideFromDepth = l.farSideFromDepth;
  return h;
}

namespace {
constexpr bool sameGroom(const GroomSettings& g, const hp::GroomSettings& h) {
  return g.clumpsPerTriangle == h.clumpsPerTriangle && g.clumpStrength == h.clumpStrength &&
         g.clumpShape == h.clumpShape && g.curlRadius == h.curlRadius && g.curlTurns == h.curlTurns &&
         g.curlVariation == h.curlVariation && g.frizzAmplitude == h.frizzAmplitude &&
         g.frizzFrequency == h.frizzFrequency && g.frizzHairline == h.frizzHairline &&
         g.frizzHairlineWidth == h.frizzHairlineWidth;
}
}  // namespace
// One default for both: the public groom starts from the scenes' recommended one, none() is the bare blend.
static_assert(sameGroom(GroomSettings{}, hp::recommendedGroom()) && sameGroom(GroomSettings::none(), hp::GroomSettings{}));
static_assert(SimulationSettings{}.volume == hp::SimulationParams{}.volume &&
              SimulationSettings{}.friction == hp::SimulationParams{}.friction &&
              SimulationSettings{}.volumeTarget == hp::SimulationParams{}.volumeTarget &&
              SimulationSettings{}.gridResolution == hp::SimulationParams{}.gridResolution);

hp::GroomSettings groom(const GroomSettings& g) {
  hp::GroomSettings h;
  h.clumpsPerTriangle = g.clumpsPerTriangle;
  h.clumpStrength = g.clumpStrength;
  h.clumpShape = g.clumpShape;
  h.curlRadius = g.curlRadius;
  h.curlTurns = g.curlTurns;
  h.curlVariation = g.curlVariation;
  h.frizzAmplitude = g.frizzAmplitude;
  h.frizzFrequency = g.frizzFrequency;
  h.frizzHairline = g.frizzHairline;
  h.frizzHairlineWidth = g.frizzHairlineWidth;
  return h;
}

hp::SimulationParams simulation(const SimulationSettings& s) {
  hp::SimulationParams p;
  p.dt = s.dt;
  p.substeps = s.substeps;
  p.iterations = s.iterations;
  p.gravity = dvec(s.gravity);
  p.damping = s.damping;
  p.pearlRadius = s.pearlRadius;
  p.stiffness = s.stiffness;
  p.stiffnessFalloff = s.stiffnessFalloff;
  p.localStiffness = s.localStiffness;
  p.maxSpeed = s.maxSpeed;
  p.volume = s.volume;
  p.volumeTarget = s.volumeTarget;
  p.friction = s.friction;
  p.gridResolution = s.gridResolution;
  p.windDirection = dvec(s.windDirection);
  p.windStrength = s.windStrength;
  p.windGust = s.windGust;
  p.windGustFrequency = s.windGustFrequency;
  return p;
}

hp::ScalpInput scalp(const ScalpInput& s) {
  hp::ScalpInput h;
  h.kind = s.kind == ScalpInput::Kind::RootFrames ? hp::ScalpInput::Kind::RootFrames
           : s.kind == ScalpInput::Kind::Bones    ? hp::ScalpInput::Kind::Bones
                                                  : hp::ScalpInput::Kind::Rigid;
  h.rootFrames = s.rootFrames;
  h.rootFramesBytes = s.rootFramesBytes;
  h.rootFramesOffset = s.rootFramesOffset;
  h.boneCount = s.boneCount;
  h.skin.reserve(s.skin.size());
  for (const SkinWeights& w : s.skin)
    h.skin.push_back({glm::uvec4(w.bones[0], w.bones[1], w.bones[2], w.bones[3]),
                      glm::vec4(w.weights[0], w.weights[1], w.weights[2], w.weights[3])});
  return h;
}

// The public default is the library's (shaders/shared/render.h).
static_assert(InstanceSettings{}.skinBounceSamples == hp::gpu::RENDER_BOUNCE_STRAND_SAMPLES);
static_assert(InstanceSettings{}.skinBounceAtGuides == hp::compute::StrandOptions{}.bounceAtGuides);

hp::InstanceSettings instance(const InstanceSettings& s) {
  hp::InstanceSettings h;
  h.simulation = simulation(s.simulation);
  h.material = material(s.material);
  h.lutMode = fibre(s.fibre);
  h.strands.verticesPerStrand = s.verticesPerStrand;
  h.strands.bounceSamples = s.skinBounceSamples;
  h.strands.bounceAtGuides = s.skinBounceAtGuides;
  h.strands.guidesOnly = s.guidesOnly;
  h.look = look(s.look);
  h.scalp = scalp(s.scalp);
  h.drawHead = s.drawHead;
  h.lod = s.lod;
  h.groom = groom(s.groom);
  return h;
}

hp::LightSpec light(const Light& l) {
  hp::LightSpec h;
  h.type = l.type == Light::Type::Spot    ? hp::LightSpec::Type::Spot
           : l.type == Light::Type::Point ? hp::LightSpec::Type::Point
                                          : hp::LightSpec::Type::Directional;
  h.direction = vec(l.direction);
  h.color = vec(l.color);
  h.intensity = l.intensity;
  h.position = vec(l.position);
  h.coneDeg = l.coneDeg;
  h.range = l.range;
  h.shadows = l.shadows;
  return h;
}

hp::View view(const View& v) {
  hp::View h;
  h.camera.view = mat(v.view);
  h.camera.proj = mat(v.projection);
  h.camera.position = vec(v.eye);
  h.camera.fovY = v.fovY;
  h.extent = v.extent;
  h.index = v.index;
  h.lines = v.lines;
  h.jitter = {v.jitterX, v.jitterY};
  if (v.hasPrevious) h.previousViewProj = mat(v.previousViewProjection);
  h.fromApplication = true;
  return h;
}

hp::HeadMotion motion(const HeadMotion& m) { return {mat(m.from), mat(m.to), m.time, m.teleport}; }

std::vector<glm::mat4> mats(std::span<const Mat4> m) {
  std::vector<glm::mat4> out;
  out.reserve(m.size());
  for (const Mat4& one : m) out.push_back(mat(one));
  return out;
}

std::vector<hp::SphereCollider> spheres(std::span<const SphereCollider> s) {
  std::vector<hp::SphereCollider> out;
  for (const SphereCollider& c : s) out.push_back({vec(c.center), c.radius});
  return out;
}

std::vector<hp::CapsuleCollider> capsules(std::span<const CapsuleCollider> c) {
  std::vector<hp::CapsuleCollider> out;
  for (const CapsuleCollider& k : c) out.push_back({vec(k.a), vec(k.b), k.radius});
  return out;
}

hp::DensityOptions density(const Density& d) {
  hp::DensityOptions h;
  switch (d.mode) {
    case Density::Mode::PerTriangle: h.mode = hp::DensityOptions::Mode::PerTriangle; break;
    case Density::Mode::Total: h.mode = hp::DensityOptions::Mode::Total; break;
    case Density::Mode::Guides: h.mode = hp::DensityOptions::Mode::Guides; break;
    case Density::Mode::Auto: h.mode = hp::DensityOptions::Mode::Auto; break;
  }
  h.strandsPerTriangle = d.strandsPerTriangle;
  h.totalStrands = d.totalStrands;
  h.seed = d.seed;
  return h;
}
}  // namespace hairpipe::convert
