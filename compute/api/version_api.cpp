// hairpipe::versionString: the version the library was built with, from the public header.
#include "hairpipe/version.h"

namespace hairpipe {
#define HAIRPIPE_STRINGIFY2(x) #x
#define HAIRPIPE_STRINGIFY(x) HAIRPIPE_STRINGIFY2(x)
const char* versionString() noexcept {
  return HAIRPIPE_STRINGIFY(HAIRPIPE_VERSION_MAJOR) "." HAIRPIPE_STRINGIFY(HAIRPIPE_VERSION_MINOR) "." HAIRPIPE_STRINGIFY(
      HAIRPIPE_VERSION_PATCH);
}
}  // namespace hairpipe
