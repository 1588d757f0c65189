#pragma once
// Contract: the version of the hairpipe headers, and of the library linked (versionString()); the two
// agree in a correct build. Semantic versioning: the public API changes only with the minor version
// while the major version is 0.
#define HAIRPIPE_VERSION_MAJOR 0
#define HAIRPIPE_VERSION_MINOR 2
#define HAIRPIPE_VERSION_PATCH 0

namespace hairpipe {
// "MAJOR.MINOR.PATCH" of the library that was linked.
const char* versionString() noexcept;
}  // namespace hairpipe
