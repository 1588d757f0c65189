// Shared by GLSL and C++: the macros that let one header declare constants and std430 structs for both.
// In C++ everything lands in namespace hp::gpu with glm types; in GLSL the same names are plain globals.
#ifndef HP_SHARED_COMMON_H
#define HP_SHARED_COMMON_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace hp::gpu {
using uint = std::uint32_t;
using uvec2 = glm::uvec2;
using uvec4 = glm::uvec4;
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using mat4 = glm::mat4;
}  // namespace hp::gpu
#define HP_BEGIN namespace hp::gpu {
#define HP_END }
#define HP_CONST(type, name, value) inline constexpr type name = value;
#else
#define HP_BEGIN
#define HP_END
#define HP_CONST(type, name, value) const type name = value;
#endif

#endif
