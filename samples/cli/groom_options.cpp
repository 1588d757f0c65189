#include "samples/cli/groom_options.h"

#include <cmath>
#include <sstream>
#include <string>

#include "engine/core/error.h"

namespace hp::cli {
void addGroomOptions(CLI::App& cmd, GroomOptions& o) {
  const GroomSettings d = recommendedGroom();
  std::ostringstream text;
  text << "No clumps, curl or frizz (each strand the plain blend of its guides) before --clump, --curl and --frizz "
          "apply; without it the scene's groom, by default --clump "
       << d.clumpsPerTriangle << ',' << d.clumpStrength << ',' << d.clumpShape << " --curl " << d.curlRadius << ','
       << d.curlTurns << ',' << d.curlVariation << " --frizz " << d.frizzAmplitude << ',' << d.frizzFrequency << ','
       << d.frizzHairline << ',' << d.frizzHairlineWidth;
  cmd.add_flag("--no-groom", o.none, text.str());
  cmd.add_option("--clump", o.clump,
                 "Clumping COUNT,STRENGTH[,SHAPE]: COUNT clump centres per scalp triangle (0-64), pulling each "
                 "strand STRENGTH (0-1) of the way to its centre at the tip, as v^SHAPE along it (omitted: the scene's)")
      ->delimiter(',')->expected(2, 3);
  cmd.add_option("--curl", o.curl,
                 "Curl RADIUS,TURNS[,VARIATION]: helix radius (scene units), turns per unit of length, per-strand "
                 "variation 0-1 (omitted: the scene's)")
      ->delimiter(',')->expected(2, 3);
  cmd.add_option("--frizz", o.frizz,
                 "Frizz AMPLITUDE[,FREQUENCY[,HAIRLINE[,WIDTH]]]: noise across the strand at the tip (scene units, "
                 "growing as v^2), cycles per unit of length, the amplitude's extra factor at the hairline and the "
                 "distance over which it falls off by 1/e (each omitted: the scene's)")
      ->delimiter(',')->expected(1, 4);
}

void applyGroomOptions(const GroomOptions& o, GroomSettings& groom) {
  GroomSettings g = o.none ? GroomSettings{} : groom;
  if (!o.clump.empty()) {
    if (!(o.clump[0] >= 0.0f && o.clump[0] <= 64.0f && o.clump[0] == std::floor(o.clump[0])))
      throw Error("--clump: COUNT must be a whole number in [0, 64], got " + std::to_string(o.clump[0]));
    g.clumpsPerTriangle = static_cast<std::uint32_t>(o.clump[0]);
    g.clumpStrength = o.clump[1];
    if (o.clump.size() > 2) g.clumpShape = o.clump[2];
  }
  if (!o.curl.empty()) {
    g.curlRadius = o.curl[0];
    g.curlTurns = o.curl[1];
    if (o.curl.size() > 2) g.curlVariation = o.curl[2];
  }
  if (!o.frizz.empty()) {
    g.frizzAmplitude = o.frizz[0];
    if (o.frizz.size() > 1) g.frizzFrequency = o.frizz[1];
    if (o.frizz.size() > 2) g.frizzHairline = o.frizz[2];
    if (o.frizz.size() > 3) g.frizzHairlineWidth = o.frizz[3];
  }
  try {
    g.validate();
  } catch (const Error& e) {
    throw Error(std::string("--clump/--curl/--frizz: ") + e.what());
  }
  groom = g;
}
}  // namespace hp::cli
