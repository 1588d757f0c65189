#include "samples/cli/hair_grid_options.h"

namespace hp::cli {
void addHairGridOptions(CLI::App& cmd, HairGridOptions& o) {
  cmd.add_option("--volume", o.volume,
                 "Hair grid: how fast hair flows out of places denser than the target, in grid cells a frame per unit "
                 "of density change over a cell, 0..10 (default 0: off; 0.6 gives the default head a body)");
  cmd.add_option("--volume-target", o.volumeTarget,
                 "Hair grid: density the volume keeps under, in units of the rest pose's mean, 0.01..100 (default 0.5)");
  cmd.add_option("--friction", o.friction,
                 "Hair grid: fraction of velocity pulled toward the surrounding hair's per substep, 0..1 (default 0: "
                 "off; 0.1 with --volume 0.6)");
  cmd.add_option("--grid-resolution", o.resolution, "Hair grid: cells along its longest side, 4..128 (default 32)");
}

void applyHairGridOptions(const HairGridOptions& o, SimulationParams& params) {
  SimulationParams p = params;
  if (o.volume) p.volume = *o.volume;
  if (o.volumeTarget) p.volumeTarget = *o.volumeTarget;
  if (o.friction) p.friction = *o.friction;
  if (o.resolution) p.gridResolution = *o.resolution;
  p.validate();
  params = p;
}
}  // namespace hp::cli
