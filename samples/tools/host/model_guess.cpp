#include "samples/tools/host/model_guess.h"

#include <cmath>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/tfx_file.h"

namespace hp {
float unitScale(const std::string& units) {
  if (units == "m") return 1.0f;
  if (units == "cm") return 0.01f;
  if (units == "mm") return 0.001f;
  throw Error("units must be m, cm or mm, got '" + units + "'");
}

namespace {
std::string guessUnits(float radius) {
  std::string best = "m";
  float bestError = INFINITY;
  for (const char* u : {"m", "cm", "mm"}) {
    const float error = std::abs(std::log(radius * unitScale(u) / 0.1f));
    if (error < bestError) bestError = error, best = u;
  }
  return best;
}

// Mean unit direction of b - a over the pairs (zero when there are none).
glm::vec3 meanDirection(std::span<const glm::vec3> a, std::span<const glm::vec3> b) {
  glm::vec3 sum(0.0f);
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i) {
    const float len = glm::length(b[i] - a[i]);
    if (len > 0.0f) sum += (b[i] - a[i]) / len;
  }
  return a.empty() ? sum : sum / float(a.size());
}
}  // namespace

ModelGuess guessModelTransform(std::span<const glm::vec3> roots, std::span<const glm::vec3> tips,
                               std::optional<std::string> units, std::optional<UpAxis> up) {
  if (roots.empty()) throw Error("cannot guess units or up axis of a model without roots");
  ModelGuess g;
  const SphereFit fit = fitSphere(roots);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : roots) lo = glm::min(lo, p), hi = glm::max(hi, p);
  // A flat patch of roots has no meaningful sphere: half its extent stands in for the radius.
  g.headRadius = fit.fitted ? fit.sphere.radius : 0.5f * glm::length(hi - lo);
  std::ostringstream why;
  g.unitsGuessed = !units;
  g.units = units ? *units : guessUnits(g.headRadius);
  g.transform.scale = unitScale(g.units);
  if (g.unitsGuessed) why << "units " << g.units << " (head radius " << g.headRadius << " model units)";
  else why << "units " << g.units << " (given)";
  g.upGuessed = !up;
  if (up) {
    g.transform.up = *up;
    why << ", up " << upAxisName(*up) << " (given)";
  } else {
    glm::vec3 centroid(0.0f);
    for (const auto& p : roots) centroid += p / float(roots.size());
    const glm::vec3 center = fit.fitted ? fit.sphere.center : centroid;
    std::vector<glm::vec3> centers(roots.size(), center);
    const glm::vec3 rootsUp = meanDirection(centers, roots);  // where the roots sit on the head
    const glm::vec3 hang = meanDirection(roots, tips);          // where the hair goes
    const float scoreY = rootsUp.y - hang.y, scoreZ = rootsUp.z - hang.z;
    g.transform.up = scoreZ > scoreY ? UpAxis::Z : UpAxis::Y;
    why << ", up " << upAxisName(g.transform.up) << " (roots above the head center and hair hanging: score y "
        << scoreY << ", z " << scoreZ << ")";
  }
  g.reason = why.str();
  return g;
}

ModelGuess guessModelFileTransform(const std::filesystem::path& path, std::optional<std::string> units,
                                   std::optional<UpAxis> up) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  std::vector<glm::vec3> roots, tips;
  if (ext == ".obj") {
    roots = loadObjScalp(path).positions;
  } else {
    const HairFileData d = ext == ".tfx" ? tfxToHair(readTfxFile(path)) : readHairFile(path);
    const auto offsets = d.strandOffsets();
    for (std::uint32_t s = 0; s < d.strandCount; ++s) {
      roots.push_back(d.points[offsets[s]]);
      tips.push_back(d.points[offsets[s + 1] - 1]);
    }
  }
  try {
    return guessModelTransform(roots, tips, units, up);
  } catch (const Error& e) {
    throw Error(path.string() + ": " + e.what());
  }
}
}  // namespace hp
