#pragma once
// Contract: the few math types that cross hairpipe's boundary, as plain structs: an application passes
// its own math library's values by copying floats, and nothing of glm (or any other math library, or its
// configuration macros) reaches its build. Matrices are column-major (m[column * 4 + row]), as GLSL, glm
// and Vulkan's conventions have them; points are transformed as M * (x, y, z, 1).
namespace hairpipe {
struct Vec3 {
  float x = 0.0f, y = 0.0f, z = 0.0f;
};

struct Mat4 {
  float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};  // identity
  float& at(int column, int row) noexcept { return m[column * 4 + row]; }
  float at(int column, int row) const noexcept { return m[column * 4 + row]; }
};
}  // namespace hairpipe
