// `hairpipe bench head [--repeat R] [--triangles N] [--json]`: host times of the distance-field work
// done at load time: sampling the default head's field on its grid, meshing it (marching tetrahedra),
// projecting the scalp, and building a distance grid from a closed collider mesh of about N triangles
// (a UV sphere, 64 cells on its longest side). Best of R runs per stage.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/hair/default_head.h"
#include "engine/hair/head_mesh.h"
#include "engine/hair/sdf_mesh.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/command.h"

namespace {
struct Options {
  std::uint32_t repeat = 3;
  std::uint32_t triangles = 100000;
  bool json = false;
};

template <typename F>
double bestSeconds(std::uint32_t repeat, F&& work) {
  double best = 1e30;
  for (std::uint32_t r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

void run(const Options& o) {
  if (o.repeat == 0 || o.triangles < 100 || o.triangles > 20000000)
    throw hp::Error("bench head: --repeat must be >= 1 and --triangles in [100, 20000000]");
  hp::SdfGrid grid;
  hp::HeadMesh head;
  const double gridS = bestSeconds(o.repeat, [&] { grid = hp::makeDefaultHeadGrid(); });
  const double meshS = bestSeconds(o.repeat, [&] { head = hp::makeDefaultHeadMesh(grid); });
  std::size_t scalpVertices = 0;
  const double scalpS = bestSeconds(o.repeat, [&] { scalpVertices = hp::makeDefaultScalp().vertexCount(); });
  const auto stacks = std::uint32_t(std::sqrt(double(o.triangles) / 4.0));
  const hp::HeadMesh sphere = hp::makeEllipsoidMesh(glm::vec3(0.0f), glm::vec3(0.2f, 0.3f, 0.15f), 2 * stacks, stacks);
  std::vector<glm::uvec3> tris;
  for (std::size_t i = 0; i < sphere.indices.size(); i += 3)
    tris.emplace_back(sphere.indices[i], sphere.indices[i + 1], sphere.indices[i + 2]);
  hp::SdfGrid colliderGrid;
  const double colliderS = bestSeconds(o.repeat, [&] { colliderGrid = hp::meshSdf(sphere.positions, tris); });
  const nlohmann::json j = {
      {"repeat", o.repeat},
      {"head_grid", {{"nodes", grid.values.size()}, {"cell_m", grid.cell}, {"seconds", gridS}}},
      {"head_mesh", {{"vertices", head.positions.size()}, {"triangles", head.indices.size() / 3}, {"seconds", meshS}}},
      {"scalp", {{"vertices", scalpVertices}, {"seconds", scalpS}}},
      {"collider_mesh_grid", {{"triangles", tris.size()}, {"nodes", colliderGrid.values.size()}, {"seconds", colliderS}}}};
  if (o.json) {
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("default head (best of %u): field grid %zu nodes %.3f s, mesh %zu triangles %.3f s, scalp %zu vertices %.3f s\n",
              o.repeat, grid.values.size(), gridS, head.indices.size() / 3, meshS, scalpVertices, scalpS);
  std::printf("collider mesh grid: %zu triangles -> %zu nodes %.3f s\n", tris.size(), colliderGrid.values.size(), colliderS);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = hp::cli::benchSuite(app, "head", "Time the default head's field, mesh and scalp, and a collider mesh's distance grid");
  cmd->add_option("--repeat", o->repeat, "runs; the best is reported")->capture_default_str();
  cmd->add_option("--triangles", o->triangles, "triangles of the collider mesh")->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { run(*o); });
}
}  // namespace

HP_CLI_COMMAND(setup);
