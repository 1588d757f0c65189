#include "samples/cli/frame_options.h"

#include <cmath>
#include <iostream>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "samples/tools/character_clip.h"
#include "engine/core/hair/input_file.h"
#include "samples/tools/host/camera_fit.h"
#include "samples/tools/host/light_option.h"
#include "samples/cli/material_options.h"

namespace hp::cli {
namespace {
// --raster overrides the scene's; --lines are graphics lines, so they pick the graphics path unless
// the compute one was asked for by name (refused).
void applyRaster(const FrameOptions& o, hp::RenderRequest& r) {
  if (o.raster) r.scene.render.raster = hp::parseRasterMode(*o.raster);
  if (o.lines) {
    if (r.scene.render.raster == hp::RasterMode::Compute)
      throw hp::Error("--lines draws graphics lines: use --raster graphics (or auto) with it");
    r.scene.render.raster = hp::RasterMode::Graphics;
  }
  if (o.tileBudget) r.rasterSettings.tileBudget = *o.tileBudget;
  if (o.shadingSpacing) r.rasterSettings.shadingSpacing = *o.shadingSpacing;
  r.rasterSettings.validate();
}

hp::render::OpacitySettings opacitySettings(const FrameOptions& o) {
  hp::render::OpacitySettings s;
  s.enabled = !o.noShadows;
  if (o.opacityResolution) s.resolution = *o.opacityResolution;
  if (o.shadowStrands) s.shadowStrands = *o.shadowStrands;
  if (o.opacityRaster) s.raster = hp::render::parseOpacityRaster(*o.opacityRaster);
  s.deep = o.deepOpacity;
  if (o.strandOpacity) {
    s.footprint = false;  // a constant per crossing replaces the width / texel-size footprint
    s.strandOpacity = *o.strandOpacity;
  }
  if (o.shadowK) s.k = *o.shadowK;
  if (o.shadowBias) s.biasSlices = s.deepBiasSlices = *o.shadowBias;  // in the slices in effect
  hp::render::validate(s);
  return s;
}

glm::vec3 vec3Option(const std::vector<float>& v, const char* name) {
  if (v.size() != 3) throw hp::Error(std::string(name) + " takes X,Y,Z");
  const glm::vec3 p{v[0], v[1], v[2]};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw hp::Error(std::string(name) + " must be finite");
  return p;
}

// The light the single-light options set: the first one (a scene with no lights gets the default sun).
hp::LightSpec& firstLight(hp::Scene& scene) {
  if (scene.lights.empty()) scene.lights.emplace_back();
  return scene.lights.front();
}

// --light-dir X,Y,Z: the first light becomes directional, toward X,Y,Z (its colour and intensity stay).
void applyLightDir(const FrameOptions& o, hp::Scene& scene) {
  if (!o.lightDir) return;
  if (o.lightDir->size() != 3) throw hp::Error("--light-dir takes X,Y,Z");
  const glm::vec3 d{(*o.lightDir)[0], (*o.lightDir)[1], (*o.lightDir)[2]};
  if (!(glm::length(d) > 1e-6f) || !std::isfinite(glm::length(d)))
    throw hp::Error("--light-dir must be a non-zero finite vector");
  hp::LightSpec& light = firstLight(scene);
  light.direction = glm::normalize(d);
  light.type = hp::LightSpec::Type::Directional;  // overrides a scene's spot or point light
}

// --spot POS [--spot-target P] [--spot-angle DEG] [--spot-range R]: the first light becomes a spot aimed
// at the target (default: the camera's target), keeping its colour, intensity and shadows; each bad value
// names its option.
void applySpot(const FrameOptions& o, hp::Scene& scene) {
  if (!o.spot) {
    if (o.spotTarget || o.spotAngle || o.spotRange) throw hp::Error("--spot-target/--spot-angle/--spot-range need --spot");
    return;
  }
  if (o.lightDir) throw hp::Error("--spot and --light-dir are exclusive");
  const glm::vec3 position = vec3Option(*o.spot, "--spot");
  const glm::vec3 target = o.spotTarget ? vec3Option(*o.spotTarget, "--spot-target") : scene.camera.target;
  if (glm::length(position - target) < 1e-6f) throw hp::Error("--spot-target must differ from the --spot position");
  const float angle = o.spotAngle.value_or(30.0f);
  if (!(angle > 0.0f && angle <= 80.0f)) throw hp::Error("--spot-angle must be in (0, 80] degrees");
  const float range = o.spotRange.value_or(0.0f);
  if (!(std::isfinite(range) && range >= 0.0f)) throw hp::Error("--spot-range must be >= 0 (0: no distance falloff)");
  hp::LightSpec light = hp::LightSpec::makeSpot(position, target, angle);
  hp::LightSpec& first = firstLight(scene);
  light.range = range;
  light.color = first.color;
  light.intensity = first.intensity;
  light.shadows = first.shadows;
  first = light;
}

// --light options first (they replace the scene's lights); then --light-dir and --spot change the first
// light, as they change a scene's.
void applyLights(const FrameOptions& o, hp::Scene& scene) {
  replaceLights(o.lights, scene);
  applyLightDir(o, scene);
  applySpot(o, scene);
  hp::validateLights(scene.lights);
}

}  // namespace

void replaceLights(const std::vector<std::string>& specs, hp::Scene& scene) {
  if (specs.empty()) return;
  if (specs.size() > hp::kMaxSceneLights)
    throw hp::Error("--light is given " + std::to_string(specs.size()) + " times: at most " +
                    std::to_string(hp::kMaxSceneLights) + " lights");
  scene.lights.clear();
  for (const std::string& spec : specs) {
    try {
      scene.lights.push_back(hp::parseLightOption(spec, scene.camera.target));
    } catch (const hp::Error& e) {
      throw hp::Error("--light '" + hp::excerpt(spec, 120) + "': " + e.what());
    }
  }
}

void addLightOption(CLI::App& cmd, std::vector<std::string>& specs) {
  cmd.add_option("--light", specs,
                 std::string("A light, repeatable (up to 8; replaces the scene's lights, the first 4 with shadows "
                             "get shadow maps): ") + hp::lightOptionSyntax() +
                     "; e.g. spot:pos=0.3,0.4,0.6:cone=35:range=0.8 (target default: the camera target)")
      ->allow_extra_args(false);
}

hp::RenderRequest makeRenderRequest(const FrameOptions& o, const CLI::App& cmd) {
  hp::RenderRequest r;
  r.scene = hp::cli::loadScene(o.scene);
  if (o.width) r.scene.render.width = *o.width;
  if (o.height) r.scene.render.height = *o.height;
  if (o.msaa) r.scene.render.msaa = *o.msaa;
  if (o.density) {
    r.scene.density.mode = hp::DensityOptions::Mode::Total;
    r.scene.density.totalStrands = *o.density;
    r.scene.density.validate();
  }
  if (o.ownStrands) r.scene.density.mode = hp::DensityOptions::Mode::Guides;
  if (o.orbit) {
    if (!std::isfinite(*o.orbit)) throw hp::Error("--camera-orbit must be a finite angle in degrees, got " + hp::numberText(*o.orbit));
    r.scene.camera.orbitDeg = *o.orbit;
  }
  applyLights(o, r.scene);
  applyGroomOptions(o.groom, r.scene.groom);
  applyHairGridOptions(o.grid, r.scene.simulation);
  if (materialGiven(cmd)) r.scene.material = o.material;
  if (r.scene.render.width == 0 || r.scene.render.height == 0 || r.scene.render.width > 16384 ||
      r.scene.render.height > 16384)
    throw hp::Error("--width/--height must be in [1, 16384]");
  r.settleFrames = o.frames;
  if (const auto clip = hp::clipOfAnimate(o.animate)) r.characterClip = *clip;
  else r.animation = hp::parseHeadAnimation(o.animate);
  r.lutMode = hp::parseLutMode(o.lutMode);
  r.lines = o.lines;
  r.guidesOnly = o.guidesOnly;
  if (o.bounceSamples < 2 || o.bounceSamples > hp::gpu::MAX_VERTICES_PER_STRAND)
    throw hp::Error("--bounce-samples must be in [2, " + std::to_string(hp::gpu::MAX_VERTICES_PER_STRAND) + "], got " +
                    std::to_string(o.bounceSamples));
  r.bounceSamples = o.bounceSamples;
  r.drawHead = !o.hairOnly;
  if (!o.lod.empty()) {
    r.lod = {true, o.lod[0], o.lod[1], o.lod[2]};
    try {
      hp::validate(r.lod);
    } catch (const hp::Error& e) {
      throw hp::Error(std::string("--lod: ") + e.what());
    }
  }
  r.exposure = o.exposure;
  applyEnvironmentOptions(o.environment, r);
  if (o.ambient) r.look.ambient = *o.ambient;
  if (o.scattering) {
    r.look.scattering = hp::render::parseScattering(*o.scattering);
    if (r.look.scattering == hp::render::Scattering::Dual && o.lutMode != "physical")
      throw hp::Error("--scattering dual needs the physical fibre model (--lut-mode physical)");
  }
  if (o.skinBounce) {
    if (*o.skinBounce != "on" && *o.skinBounce != "off")
      throw hp::Error("--skin-bounce must be on or off, got '" + o.skinBounce->substr(0, 40) + "'");
    r.look.skinBounce = *o.skinBounce == "on";
  }
  if (o.skinIndirect) {
    if (*o.skinIndirect != "on" && *o.skinIndirect != "off")
      throw hp::Error("--skin-indirect must be on or off, got '" + o.skinIndirect->substr(0, 40) + "'");
    r.look.skinIndirect = *o.skinIndirect == "on";
  }
  if (o.farSide) {
    if (*o.farSide != "depth" && *o.farSide != "open")
      throw hp::Error("--far-side must be depth or open, got '" + o.farSide->substr(0, 40) + "'");
    r.look.farSideFromDepth = *o.farSide == "depth";
  }
  if (o.wrap) r.look.wrap = *o.wrap;  // range checked by look.validate below
  if (o.skinColor) {
    r.look.skinColor = vec3Option(*o.skinColor, "--skin-color");
    if (glm::any(glm::lessThan(r.look.skinColor, glm::vec3(0.0f))) || glm::any(glm::greaterThan(r.look.skinColor, glm::vec3(1.0f))))
      throw hp::Error("--skin-color components must be in [0, 1]");
  }
  r.look.validate();
  r.opacity = opacitySettings(o);
  applyRaster(o, r);
  return r;
}

// The character mesh and how the roots bound to it, on stderr and as JSON.
nlohmann::json characterReport(const hp::HairAsset& asset) {
  const hp::CharacterMesh& m = *asset.character;
  const hp::RootBindings& b = asset.rootBindings;
  std::cerr << "hairpipe: mesh " << m.source << ": " << m.vertexCount() << " vertices, " << m.triangleCount()
            << " triangles, " << m.skeleton.size() << " joints, " << m.animations.size() << " animations; the "
            << b.roots.size() << " guide roots bound to it lie " << b.meanDistance << " from it on average (at most "
            << b.maxDistance << "), " << b.farRoots << " farther than " << b.farDistance << "\n";
  return {{"source", m.source},           {"vertices", m.vertexCount()},   {"triangles", m.triangleCount()},
          {"joints", m.skeleton.size()},   {"animations", m.animations.size()}, {"roots_far", b.farRoots},
          {"far_distance", b.farDistance}, {"root_distance_mean", b.meanDistance}, {"root_distance_max", b.maxDistance}};
}

// A model loaded without a scene: frame the camera on its hair (the orbit and elevation stay). Any
// frame: refuse one in which no guide particle falls inside the view, naming why.
nlohmann::json frameCamera(Scene& scene, const hp::HairAsset& asset) {
  nlohmann::json guessed = nlohmann::json::object();
  if (scene.fitCamera) {
    hp::fitCameraToPoints(scene.camera, asset.guides.positions);
    const auto& c = scene.camera;
    guessed = {{"model", scene.guessed},
               {"camera", {{"target", {c.target.x, c.target.y, c.target.z}}, {"distance", c.distance}}}};
    std::cerr << "hairpipe: guessed " << scene.guessed << "; camera framed on the hair (target " << c.target.x
              << ", " << c.target.y << ", " << c.target.z << ", distance " << c.distance << ")\n";
  }
  if (asset.fittedCollider && !asset.colliders.empty()) {
    const float radius = asset.colliders.front().radius;
    guessed["collider"] = {{"fitted_sphere_radius", radius}, {"drawn", false}};
    std::cerr << "hairpipe: " << asset.name << " has no head mesh: the sphere fitted to its roots (radius " << radius
              << ") keeps the hair out but is not drawn\n";
  }
  // Bare only where strands are blended: a model drawing its own strands leaves no triangle bare.
  if (asset.partedTriangles > 0 && hp::resolvedMode(scene.density, asset.guides.guideCount()) != hp::DensityOptions::Mode::Guides) {
    guessed["bare_scalp_triangles"] = asset.partedTriangles;
    std::cerr << "hairpipe: " << asset.name << ": " << asset.partedTriangles << " scalp triangles left bare: their guides "
              << "part around the head, and strands blended from them would run through it\n";
  }
  if (asset.character) guessed["mesh"] = characterReport(asset);
  const float aspect = float(scene.render.width) / float(scene.render.height);
  if (hp::pointsInView(scene.camera, aspect, asset.guides.positions) == 0) {
    const auto& c = scene.camera;
    throw hp::Error("no hair is visible: all " + std::to_string(asset.guides.positions.size()) +
                    " guide particles of " + asset.name + " are outside the camera's view (target " +
                    hp::numberText(c.target.x) + ", " + hp::numberText(c.target.y) + ", " + hp::numberText(c.target.z) +
                    ", distance " + hp::numberText(c.distance) + ", orbit " + hp::numberText(c.orbitDeg) +
                    "); check the model's units/up axis or the camera");
  }
  return guessed;
}


void addFrameOptions(CLI::App& cmd, FrameOptions& o) {
  addSceneOptions(cmd, o.scene);
  addMaterialOptions(cmd, o.material);
  cmd.add_option("--frames", o.frames,
                 "Frames simulated before the rendered one (default 90); with render --sequence, the frames rendered");
  cmd.add_option("--width", o.width, "Image width (default: scene, 1280)");
  cmd.add_option("--height", o.height, "Image height (default: scene, 720)");
  cmd.add_option("--msaa", o.msaa, "Samples per pixel: 1, 2, 4 or 8 (default: scene, 4); the head's in both rasters (the compute raster's hair is analytic and reads them at the head's edges), the hair's in the graphics raster");
  cmd.add_option("--raster", o.raster,
                 "Hair drawing: compute (tile rasterizer, analytic coverage), graphics (MSAA ribbons) or auto "
                 "(default: scene, auto = compute)");
  cmd.add_option("--tile-budget", o.tileBudget, "Compute raster: list entries kept per 8x8 tile (default 16384)");
  cmd.add_option("--shading-spacing", o.shadingSpacing,
                 "Compute raster: pixels within which a strand's every other vertex takes its neighbours' mean instead "
                 "of being shaded, 0-4096; 0 shades every vertex (default " +
                     std::to_string(int(hp::compute::RasterSettings{}.shadingSpacing)) + ")");
  auto* density = cmd.add_option("--density", o.density,
                                 "Render strands in total, interpolated between the guides (default: the scene's; "
                                 "without one, a model of at least 20000 strands draws its own, else 20000)");
  cmd.add_flag("--own-strands", o.ownStrands, "Draw the model's own strands: one render strand on every guide")
      ->excludes(density);
  addLightOption(cmd, o.lights);
  cmd.add_option("--light-dir", o.lightDir, "Direction toward the first light, X,Y,Z (it becomes directional)")
      ->delimiter(',')->expected(3);
  cmd.add_option("--spot", o.spot, "The first light becomes a spot at X,Y,Z")->delimiter(',')->expected(3);
  cmd.add_option("--spot-target", o.spotTarget, "Point the spot aims at, X,Y,Z (default: the camera target)")
      ->delimiter(',')->expected(3);
  cmd.add_option("--spot-angle", o.spotAngle, "Spot cone half-angle in degrees, (0, 80] (default 30)");
  cmd.add_option("--spot-range", o.spotRange, "Spot inverse-square falloff, 1 at this distance (default 0: none)");
  cmd.add_option("--camera-orbit", o.orbit, "Camera orbit around the head in degrees (0: from the front)");
  cmd.add_option("--lut-mode", o.lutMode, "fibre model: physical (energy-conserving, default), or the paper's model as float, paper or direct");
  cmd.add_option("--animate", o.animate, "Head motion while settling: none, nod, turn, shake, teleport, or clip:NAME (an animation clip of the --mesh "
                 "character: its body is posed, collided with and drawn, and the roots follow its bones)");
  cmd.add_option("--exposure", o.exposure, "Exposure multiplier before tonemapping (default 1)");
  cmd.add_option("--ambient", o.ambient,
                 "Ambient fill light in [0, 10] (default 0.06; the reference's uniform sky radiance)");
  cmd.add_option("--scattering", o.scattering,
                 "dual (default): adds the light the hair in front scattered forward and the hair around scattered "
                 "back (physical fibre model), or single");
  cmd.add_option("--skin-bounce", o.skinBounce,
                 "on or off: adds the sunlight the skin reflects onto the hair (default on)");
  cmd.add_option("--skin-indirect", o.skinIndirect,
                 "on or off: the head's indirect light, the sky it sees past its own shape and the light its skin "
                 "passes on to itself (default on); off: the open sky on all skin");
  cmd.add_option("--far-side", o.farSide,
                 "Compute raster: the sky on a hair fibre's far side: depth (default; where the depth image lies "
                 "behind the fibre, the light the hair beneath passes on) or open (the open sky everywhere)");
  cmd.add_option("--wrap", o.wrap,
                 "The skin's wrap lighting, [0, 1]: light reaches past the terminator as (wrap + N.L) / (1 + wrap) "
                 "(default 0: Lambertian, as the reference's skin; the skin's indirect light, --skin-indirect, stands for what the wrap imitated)");
  cmd.add_option("--skin-color", o.skinColor, "Skin albedo R,G,B, each in [0, 1] (default 0.62,0.45,0.36)")
      ->delimiter(',')->expected(3);
  cmd.add_flag("--lines", o.lines, "Draw strands as lines instead of ribbons");
  cmd.add_flag("--guides-only", o.guidesOnly, "Draw the smoothed guides only (no interpolation)");
  addEnvironmentOptions(cmd, o.environment);
  addGroomOptions(cmd, o.groom);
  addHairGridOptions(cmd, o.grid);
  cmd.add_option("--bounce-samples", o.bounceSamples,
                 "Points per strand where the skin's bounce is gathered, the shading interpolating between them, "
                 "[2, 256] (default 8; the vertex count, 36, gathers at every vertex)");
  cmd.add_option("--lod", o.lod,
                 "Level of detail START,END,MIN: beyond START (distance from the eye to the head) the strands thin "
                 "to the fraction MIN at END, widened to keep the hair's coverage")
      ->delimiter(',')->expected(3);
  cmd.add_flag("--hair-only", o.hairOnly,
               "Draw the hair without the model's head (no head drawn, in the shadows or bouncing light; "
               "collisions unchanged)");
  cmd.add_flag("--no-shadows", o.noShadows, "Turn the opacity shadow maps off");
  cmd.add_option("--opacity-resolution", o.opacityResolution, "Opacity map texels per side, 16-4096 (default 512)");
  cmd.add_option("--shadow-strands", o.shadowStrands,
                 "Render strands drawn into the opacity maps at most, an even sample widened to keep the hair's "
                 "opacity; 0: all (default " + std::to_string(hp::render::OpacitySettings{}.shadowStrands) + ")");
  cmd.add_flag("--deep-opacity,!--global-opacity", o.deepOpacity,
               "Deep opacity maps (default; compute opacity path): slices start at each texel's first hair, 4x finer; "
               "--global-opacity: 16 slices over the whole hair");
  cmd.add_option("--opacity-raster", o.opacityRaster,
                 "How strands reach the opacity maps: auto (default: compute where its bins fit the device), compute (splats) or graphics (lines)");
  cmd.add_option("--strand-opacity", o.strandOpacity, "Constant opacity a strand adds per opacity-map texel instead of its footprint (width / texel size, the default)");
  cmd.add_option("--shadow-k", o.shadowK, "Extinction k in T = exp(-k alpha) (default 1)");
  cmd.add_option("--shadow-bias", o.shadowBias, "Shadow lookup bias toward the light, in the slices in effect (default: 0.25 deep slices, 1 global slice)");
}
}  // namespace hp::cli
