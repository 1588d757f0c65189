// `hairpipe bench head [--repeat R] [--triangles N] [--json]`: host times of the distance-field work
// done at load time: sampling the default head's field on its grid (narrow band), meshing it (marching
// cubes), projecting the scalp and marking the mesh's scalp vertices (together: the head build),
// and building a distance grid from a closed collider mesh of about N triangles (a UV sphere, 64 cells
// on its longest side). Best of R runs per stage, wall clock and process CPU time.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_mesh.h"
#include "engine/core/hair/mesh_simplify.h"
#include "engine/core/hair/sdf_mesh.h"
#include "engine/core/hair/skin_transfer.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/command.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench_head {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct Options {
  std::uint32_t repeat = 3;
  std::uint32_t triangles = 100000;
  bool json = false;
};

// Best wall-clock and best process CPU seconds (all threads) of R runs: on a loaded machine the wall
// clock includes waiting for a core, the CPU time does not.
struct Seconds {
  double wall = 1e30, cpu = 1e30;
  Seconds operator+(const Seconds& o) const { return {wall + o.wall, cpu + o.cpu}; }
};

template <typename F>
Seconds bestSeconds(std::uint32_t repeat, F&& work) {
  Seconds best;
  for (std::uint32_t r = 0; r < repeat; ++r) {
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    work();
    best.cpu = std::min(best.cpu, double(std::clock() - cpuStart) / CLOCKS_PER_SEC);
    best.wall = std::min(best.wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

nlohmann::json toJson(const Seconds& s) { return {{"seconds", s.wall}, {"cpu_seconds", s.cpu}}; }

void run(const Options& o) {
  if (o.repeat == 0 || o.triangles < 100 || o.triangles > 20000000)
    throw hp::Error("bench head: --repeat must be >= 1 and --triangles in [100, 20000000]");
  hp::NarrowBandGrid field;
  hp::HeadMesh head;
  const Seconds gridS = bestSeconds(o.repeat, [&] { field = hp::makeDefaultHeadField(); });
  const Seconds meshS = bestSeconds(o.repeat, [&] { head = hp::makeDefaultHeadMesh(field); });
  const hp::SdfGrid& grid = field.grid;
  hp::ScalpMesh scalp;
  const Seconds scalpS = bestSeconds(o.repeat, [&] { scalp = hp::makeDefaultScalp(); });
  const std::size_t scalpVertices = scalp.vertexCount();
  const Seconds markS = bestSeconds(o.repeat, [&] { hp::markScalp(head, scalp.positions); });
  const std::size_t marchedTriangles = head.indices.size() / 3;
  hp::HeadMesh simplified;
  // simplifyMesh itself, not simplifyDefaultHeadMesh: that one reads HAIRPIPE_CACHE_DIR's entry when there is one.
  const Seconds simplifyS = bestSeconds(o.repeat, [&] {
    simplified = hp::simplifyMesh(head, hp::kDefaultHeadSimplify);
  });
  head = std::move(simplified);
  const Seconds totalS = gridS + meshS + scalpS + markS + simplifyS;
  // The skin's transfer of the simplified mesh (the one drawn): what creating an instance adds (once per mesh
  // and Renderer), not part of the build.
  const Seconds transferS = bestSeconds(o.repeat, [&] { (void)hp::computeSkinTransfer(head); });
  const auto stacks = std::uint32_t(std::sqrt(double(o.triangles) / 4.0));
  const hp::HeadMesh sphere = hp::makeEllipsoidMesh(glm::vec3(0.0f), glm::vec3(0.2f, 0.3f, 0.15f), 2 * stacks, stacks);
  std::vector<glm::uvec3> tris;
  for (std::size_t i = 0; i < sphere.indices.size(); i += 3)
    tris.emplace_back(sphere.indices[i], sphere.indices[i + 1], sphere.indices[i + 2]);
  hp::SdfGrid colliderGrid;
  const Seconds colliderS = bestSeconds(o.repeat, [&] { colliderGrid = hp::meshSdf(sphere.positions, tris); });
  const nlohmann::json j = {
      {"repeat", o.repeat},
      {"head_grid", {{"nodes", grid.values.size()}, {"exact_nodes", field.exactNodes}, {"cell_m", grid.cell}, {"time", toJson(gridS)}}},
      {"head_mesh", {{"triangles", marchedTriangles}, {"time", toJson(meshS)}}},
      {"scalp", {{"vertices", scalpVertices}, {"time", toJson(scalpS)}}},
      {"scalp_marking", {{"time", toJson(markS)}}},
      {"simplify", {{"vertices", head.positions.size()}, {"triangles", head.indices.size() / 3}, {"time", toJson(simplifyS)}}},
      {"head_total", {{"time", toJson(totalS)}}},
      {"skin_transfer", {{"rays_per_vertex", hp::SkinTransferOptions{}.raysPerVertex}, {"time", toJson(transferS)}}},
      {"collider_mesh_grid", {{"triangles", tris.size()}, {"nodes", colliderGrid.values.size()}, {"time", toJson(colliderS)}}}};
  if (o.json) {
    std::cout << hp::jsonText(j) << "\n";
    return;
  }
  std::printf("default head, best of %u, seconds wall (CPU, all threads):\n", o.repeat);
  std::printf("  field grid   %8zu nodes (%zu exact)  %.4f (%.4f)\n", grid.values.size(), field.exactNodes, gridS.wall, gridS.cpu);
  std::printf("  mesh         %8zu triangles        %.4f (%.4f)\n", marchedTriangles, meshS.wall, meshS.cpu);
  std::printf("  scalp        %8zu vertices         %.4f (%.4f)\n", scalpVertices, scalpS.wall, scalpS.cpu);
  std::printf("  scalp marking                          %.4f (%.4f)\n", markS.wall, markS.cpu);
  std::printf("  simplified   %8zu triangles        %.4f (%.4f)\n", head.indices.size() / 3, simplifyS.wall, simplifyS.cpu);
  std::printf("  total                                  %.4f (%.4f)\n", totalS.wall, totalS.cpu);
  std::printf("  skin transfer (%u rays a vertex)        %.4f (%.4f)\n", hp::SkinTransferOptions{}.raysPerVertex,
              transferS.wall, transferS.cpu);
  std::printf("collider mesh grid: %zu triangles -> %zu nodes %.3f (%.3f)\n", tris.size(), colliderGrid.values.size(),
              colliderS.wall, colliderS.cpu);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  auto* cmd = hp::cli::benchSuite(app, "head", "Time the default head's field, mesh, scalp and skin transfer, and a collider mesh's distance grid");
  cmd->add_option("--repeat", o->repeat, "runs; the best is reported")->capture_default_str();
  cmd->add_option("--triangles", o->triangles, "triangles of the collider mesh")->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON");
  cmd->callback([o] { run(*o); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_bench_head
