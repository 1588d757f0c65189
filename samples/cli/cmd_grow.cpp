// `hairpipe grow --scalp FILE.obj --out FILE.hair [growth options]`: grows one guide per scalp vertex
// (paper §1) and writes the guides as a .hair file, atomically: bad input never leaves a partial or
// stale output behind.
#include <iostream>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/guide_growth.h"
#include "engine/core/hair/hair_export.h"
#include "engine/core/hair/obj_import.h"
#include "samples/cli/command.h"
#include "samples/cli/output_paths.h"

namespace hp::cli::cmd_grow {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct GrowCommand {
  std::string scalp;
  std::string out;
  hp::GrowthOptions growth;
  float scale = 1.0f;
  std::string up = "y";
  bool fitCollider = false;
};

void run(const GrowCommand& c) {
  hp::ModelTransform transform;
  transform.scale = c.scale;
  transform.up = hp::parseUpAxis(c.up);
  hp::cli::prepareOutputFile({"--out", c.out}, {{"--scalp", c.scalp}});
  hp::ScalpMesh scalp = hp::loadObjScalp(c.scalp, transform);
  std::vector<hp::SphereCollider> colliders;
  if (c.fitCollider) colliders.push_back(hp::fitSphere(scalp.positions).sphere);
  hp::GuideSet guides = hp::growGuides(scalp, c.growth, colliders);
  hp::writeHairFile(c.out, hp::guidesToHair(guides, "hairpipe grow " + std::filesystem::path(c.scalp).filename().string()));
  std::cout << "grew " << guides.guideCount() << " guides x " << guides.particlesPerGuide << " particles from "
            << c.scalp;
  if (scalp.droppedDegenerateTriangles)
    std::cout << " (" << scalp.droppedDegenerateTriangles << " zero-area faces dropped)";
  std::cout << " -> " << c.out << "\n";
}

void setup(CLI::App& app) {
  auto c = std::make_shared<GrowCommand>();
  auto* cmd = app.add_subcommand("grow", "Grow guide strands on an OBJ scalp and write them as .hair");
  cmd->add_option("--scalp", c->scalp, "scalp mesh (.obj)")->required();
  cmd->add_option("--out", c->out, "output .hair file")->required();
  cmd->add_option("--particles", c->growth.particlesPerGuide, "particles per guide, 2-64")->capture_default_str();
  cmd->add_option("--length", c->growth.length, "mean guide length (output units)")->capture_default_str();
  cmd->add_option("--variation", c->growth.lengthVariation, "relative random length variation, [0, 1)")
      ->capture_default_str();
  cmd->add_option("--ratio", c->growth.segmentRatio, "segment length ratio tip-ward, [1, 4]")->capture_default_str();
  cmd->add_option("--bend", c->growth.bend, "per-segment turn toward gravity, [0, 1]")->capture_default_str();
  cmd->add_option("--seed", c->growth.seed, "random seed")->capture_default_str();
  cmd->add_option("--scale", c->scale, "scale applied to the OBJ (0.01: centimetres to metres)")->capture_default_str();
  cmd->add_option("--up", c->up, "up axis of the OBJ: y or z")->capture_default_str();
  cmd->add_flag("--fit-collider", c->fitCollider, "slide guides over a sphere fitted to the scalp");
  cmd->callback([c] { run(*c); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_grow
