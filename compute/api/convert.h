#pragma once
// Contract: the public value types (hairpipe/settings.h) into the implementation's (glm-based) ones,
// field by field; no checks here (the implementation's validate() names a bad field).
#include <glm/glm.hpp>

#include <span>
#include <vector>

#include "compute/strands/simulate_pass.h"
#include "engine/core/hair/collider.h"
#include "engine/core/hair/scene.h"
#include "compute/renderer/renderer_settings.h"
#include "hairpipe/asset.h"
#include "hairpipe/settings.h"

namespace hairpipe::convert {
glm::vec3 vec(const Vec3& v);
Vec3 vec(const glm::vec3& v);
glm::dvec3 dvec(const std::array<double, 3>& v);
glm::mat4 mat(const Mat4& m);
Mat4 mat(const glm::mat4& m);
std::vector<glm::mat4> mats(std::span<const Mat4> m);

hp::RasterMode raster(RasterMode mode);
RasterMode raster(hp::RasterMode mode);
hp::LutMode fibre(FibreModel model);
hp::RendererSettings renderer(const RendererSettings& s);
hp::HairMaterial material(const Material& m);
hp::render::LookSettings look(const LookSettings& l);
hp::GroomSettings groom(const GroomSettings& g);
hp::SimulationParams simulation(const SimulationSettings& s);
hp::ScalpInput scalp(const ScalpInput& s);
hp::InstanceSettings instance(const InstanceSettings& s);
hp::LightSpec light(const Light& l);
hp::View view(const View& v);
hp::HeadMotion motion(const HeadMotion& m);
std::vector<hp::SphereCollider> spheres(std::span<const SphereCollider> s);
std::vector<hp::CapsuleCollider> capsules(std::span<const CapsuleCollider> c);
hp::DensityOptions density(const Density& d);
}  // namespace hairpipe::convert
