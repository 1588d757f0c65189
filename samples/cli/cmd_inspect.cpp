// `hairpipe inspect FILE [--json]`: what is in a .hair model (strands, points, points per strand,
// bounding box, arrays present, the head sphere fitted to the roots), a TressFX .tfx model (version,
// strands, vertices per strand, arrays, bounds, head sphere), a TressFX .tfxbone skinning file (bones,
// strands, influences, weights not summing to 1), an OBJ scalp (vertices, triangles, dropped degenerate
// faces, bounding box, fitted sphere) or a character mesh (.ply, .gltf, .glb, .tfxmesh: vertices, triangles,
// joints, animation clips, bounding box). Bad files exit 1 with a message.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/fit_sphere.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/mesh_file.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "engine/core/hair/tfx_file.h"
#include "samples/cli/command.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_inspect {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct InspectOptions {
  std::string file;
  bool json = false;
};

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The sphere fitted to `sphereOf`; for roots (`roots`) also the collider an import makes of it.
nlohmann::json boundsAndSphere(std::span<const glm::vec3> points, std::span<const glm::vec3> sphereOf, bool roots) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  hp::SphereFit fit = hp::fitSphere(sphereOf);
  nlohmann::json sphere = {{"center", vec(fit.sphere.center)}, {"radius", fit.sphere.radius},
                           {"fitted", fit.fitted}, {"rms_error", fit.rmsError}};
  if (roots) sphere["collider_radius"] = hp::colliderUnderRoots(fit.sphere, sphereOf).radius;
  return {{"bbox", {{"min", vec(lo)}, {"max", vec(hi)}}}, {"head_sphere", sphere}};
}

nlohmann::json inspectHair(const std::filesystem::path& path) {
  hp::HairFileData d = hp::readHairFile(path);
  std::uint32_t lo = UINT32_MAX, hi = 0;
  std::vector<glm::vec3> roots;
  auto offsets = d.strandOffsets();
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    lo = std::min(lo, d.strandPointCount(s));
    hi = std::max(hi, d.strandPointCount(s));
    roots.push_back(d.points[offsets[s]]);
  }
  nlohmann::json arrays = nlohmann::json::array();
  if (!d.segments.empty()) arrays.push_back("segments");
  arrays.push_back("points");
  if (!d.thickness.empty()) arrays.push_back("thickness");
  if (!d.transparency.empty()) arrays.push_back("transparency");
  if (!d.colors.empty()) arrays.push_back("colors");
  nlohmann::json j = {{"file", path.string()}, {"format", "hair"}, {"strands", d.strandCount},
                      {"points", d.pointCount()}, {"min_points_per_strand", lo},
                      {"max_points_per_strand", hi}, {"arrays", arrays}, {"info", d.infoText()}};
  j.update(boundsAndSphere(d.points, roots, true));
  return j;
}

nlohmann::json inspectTfx(const std::filesystem::path& path) {
  const hp::TfxData d = hp::readTfxFile(path);
  std::vector<glm::vec3> points, roots;
  for (std::size_t i = 0; i < d.positions.size(); ++i) {
    points.emplace_back(d.positions[i]);
    if (i % d.verticesPerStrand == 0) roots.emplace_back(d.positions[i]);
  }
  nlohmann::json arrays = nlohmann::json::array({"positions"});
  if (!d.strandUVs.empty()) arrays.push_back("strand_uvs");
  if (!d.vertexUVs.empty()) arrays.push_back("vertex_uvs");
  if (!d.strandThickness.empty()) arrays.push_back("strand_thickness");
  if (!d.vertexColors.empty()) arrays.push_back("vertex_colors");
  nlohmann::json j = {{"file", path.string()}, {"format", "tfx"}, {"version", d.version},
                      {"strands", d.strandCount}, {"vertices_per_strand", d.verticesPerStrand},
                      {"points", points.size()}, {"arrays", arrays}};
  j.update(boundsAndSphere(points, roots, true));
  return j;
}

// A skinning file has no points: its bones, its strands and how they are weighted.
nlohmann::json inspectTfxBone(const std::filesystem::path& path) {
  const hp::TfxBoneData d = hp::readTfxBoneFile(path);
  std::size_t most = 0, unnormalised = 0;
  for (const auto& s : d.strands) {
    std::size_t used = 0;
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      used += s.weights[k] > 0.0f ? 1 : 0;
      sum += s.weights[k];
    }
    most = std::max(most, used);
    unnormalised += std::abs(sum - 1.0f) > 1e-3f ? 1 : 0;
  }
  return {{"file", path.string()}, {"format", "tfxbone"}, {"bones", d.boneNames.size()}, {"bone_names", d.boneNames},
          {"strands", d.strands.size()}, {"most_influences_per_strand", most},
          {"strands_with_weights_not_summing_to_1", unnormalised}};
}

nlohmann::json inspectObj(const std::filesystem::path& path) {
  hp::ScalpMesh m = hp::loadObjScalp(path);
  nlohmann::json j = {{"file", path.string()}, {"format", "obj"}, {"vertices", m.vertexCount()},
                      {"triangles", m.triangles.size()},
                      {"dropped_degenerate_triangles", m.droppedDegenerateTriangles}};
  j.update(boundsAndSphere(m.positions, m.positions, false));
  return j;
}

nlohmann::json inspectMesh(const std::filesystem::path& path, MeshKind kind) {
  const CharacterMesh m = loadCharacterMesh(path);
  std::vector<std::string> joints;
  for (const Joint& joint : m.skeleton) joints.push_back(joint.name);
  nlohmann::json clips = nlohmann::json::array();
  for (const AnimationClip& c : m.animations)
    clips.push_back({{"name", c.name}, {"duration_s", c.duration}, {"channels", c.channels.size()}});
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return {{"file", path.string()}, {"format", "mesh"}, {"kind", meshKindName(kind)}, {"vertices", m.vertexCount()},
          {"triangles", m.triangleCount()}, {"dropped_degenerate_triangles", m.droppedDegenerateTriangles},
          {"skinned", m.skinned()}, {"joints", joints.size()}, {"joint_names", joints}, {"animations", clips},
          {"bbox", {{"min", vec(lo)}, {"max", vec(hi)}}}};
}

void printMesh(const nlohmann::json& j) {
  std::cout << j["kind"].get<std::string>() << " mesh: " << j["vertices"] << " vertices, " << j["triangles"]
            << " triangles (" << j["dropped_degenerate_triangles"] << " degenerate dropped), "
            << (j["skinned"].get<bool>() ? "skinned" : "rigid") << ", " << j["joints"] << " joints\n";
  if (!j["joint_names"].empty()) {
    std::cout << "joints:";
    for (const auto& n : j["joint_names"]) std::cout << " " << n.get<std::string>();
    std::cout << "\n";
  }
  for (const auto& c : j["animations"])
    std::cout << "animation '" << c["name"].get<std::string>() << "': " << c["duration_s"].get<double>() << " s, "
              << c["channels"] << " channels\n";
}

std::string text3(const nlohmann::json& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  return buf;
}

void printText(const nlohmann::json& j) {
  std::cout << "file: " << j["file"].get<std::string>() << "\n";
  if (j["format"] == "mesh") {
    printMesh(j);
    std::cout << "bbox: min " << text3(j["bbox"]["min"]) << " max " << text3(j["bbox"]["max"]) << "\n";
    return;
  }
  if (j["format"] == "tfxbone") {
    std::cout << "TressFX skinning: " << j["bones"] << " bones, " << j["strands"] << " strands, up to "
              << j["most_influences_per_strand"] << " influences a strand, "
              << j["strands_with_weights_not_summing_to_1"] << " strands whose weights do not sum to 1\nbones:";
    for (const auto& n : j["bone_names"]) std::cout << " " << n.get<std::string>();
    std::cout << "\n";
    return;
  }
  if (j["format"] == "hair") {
    std::cout << "strands: " << j["strands"] << "\npoints: " << j["points"] << "\npoints per strand: min "
              << j["min_points_per_strand"] << ", max " << j["max_points_per_strand"] << "\narrays:";
    for (const auto& a : j["arrays"]) std::cout << " " << a.get<std::string>();
    std::cout << "\ninfo: \"" << j["info"].get<std::string>() << "\"\n";
  } else if (j["format"] == "tfx") {
    std::cout << "TressFX version: " << j["version"].get<double>() << "\nstrands: " << j["strands"]
              << "\nvertices per strand: " << j["vertices_per_strand"] << "\npoints: " << j["points"] << "\narrays:";
    for (const auto& a : j["arrays"]) std::cout << " " << a.get<std::string>();
    std::cout << "\n";
  } else {
    std::cout << "vertices: " << j["vertices"] << "\ntriangles: " << j["triangles"]
              << "\ndropped degenerate triangles: " << j["dropped_degenerate_triangles"] << "\n";
  }
  const auto& s = j["head_sphere"];
  std::cout << "bbox: min " << text3(j["bbox"]["min"]) << " max " << text3(j["bbox"]["max"]) << "\n"
            << "head sphere" << (s["fitted"].get<bool>() ? "" : " (stand-in: points are nearly flat)")
            << ": center " << text3(s["center"]) << " radius " << s["radius"].get<double>();
  if (s.contains("collider_radius"))
    std::cout << " (the collider an import fits: radius " << s["collider_radius"].get<double>() << ", under every root)";
  std::cout << "\n";
}

void run(const InspectOptions& o) {
  std::filesystem::path path(o.file);
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  nlohmann::json j;
  if (ext == ".hair") j = inspectHair(path);
  else if (ext == ".tfx") j = inspectTfx(path);
  else if (ext == ".tfxbone") j = inspectTfxBone(path);
  else if (ext == ".obj") j = inspectObj(path);
  else if (const auto kind = meshKindOf(path)) j = inspectMesh(path, *kind);
  else throw hp::Error(o.file + ": unknown file type (expected .hair, .tfx, .tfxbone, .obj, .ply, .gltf, .glb or .tfxmesh)");
  if (o.json) std::cout << hp::jsonText(j) << "\n";
  else printText(j);
}

void setup(CLI::App& app) {
  auto opts = std::make_shared<InspectOptions>();
  auto* cmd = app.add_subcommand("inspect",
                                 "Describe a .hair or TressFX .tfx model, a TressFX .tfxbone skinning file, an OBJ scalp or a "
                                 "character mesh (.ply, .gltf, .glb, .tfxmesh)");
  cmd->add_option("file", opts->file, "a .hair, .tfx, .tfxbone, .obj, .ply, .gltf, .glb or .tfxmesh file")->required();
  cmd->add_flag("--json", opts->json, "print JSON instead of text");
  cmd->callback([opts] { run(*opts); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_inspect
