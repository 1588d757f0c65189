// stb_image compiled for .hdr images only, from memory, with static linkage (no stbi_ symbol leaves this file).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS 16384
#include <stb/stb_image.h>

#include "samples/tools/stb_image_hdr.h"

namespace hp::stb {
void FreeStb::operator()(float* p) const { stbi_image_free(p); }

bool hdrInfo(const unsigned char* data, int size, int* width, int* height, int* channels) {
  return stbi_info_from_memory(data, size, width, height, channels) != 0;
}

FloatImage loadHdr(const unsigned char* data, int size) {
  FloatImage image;
  int channels = 0;
  image.pixels.reset(stbi_loadf_from_memory(data, size, &image.width, &image.height, &channels, 3));
  return image;
}

std::string failureReason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown";
}
}  // namespace hp::stb
