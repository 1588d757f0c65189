#pragma once
// Contract: the identity of the code this library was built from: a hash of every source file of the library
// (engine/, compute/, shaders/) and of the compiler, its version and the build type's flags, computed by the build
// (engine/build_identity.cmake). Two builds with equal identities compute the same values from the same inputs, so
// a value one of them kept on disk (disk_cache.h) is valid for the other; any edit to a source changes it.
namespace hp {
const char* buildIdentity();
}  // namespace hp
