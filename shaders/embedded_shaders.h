#pragma once
// Contract: every GLSL stage under shaders/ is compiled by glslc at build time and embedded here.
// spirv(name) returns the SPIR-V words of "name" (file name with stage suffix, e.g. "simulate.comp")
// and throws hp::Error naming the shader when it does not exist.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hp::shaders {
std::span<const std::uint32_t> spirv(const std::string& name);
std::vector<std::string> names();
}  // namespace hp::shaders
