#pragma once
// Contract: the part of stb_image (Debian's libstb-dev) that the environment reader uses: Radiance .hdr only,
// from memory, compiled in one file (stb_image_hdr.cpp) with its symbols kept inside it, at most 16384 texels
// a side. FloatImage owns stb's RGB float pixels. failureReason is stb's message for the calling thread's last
// failure.
#include <memory>
#include <string>

namespace hp::stb {
struct FreeStb {
  void operator()(float* p) const;
};
struct FloatImage {
  int width = 0, height = 0;
  std::unique_ptr<float[], FreeStb> pixels;  // width x height x 3, rows top first; null on failure
};
bool hdrInfo(const unsigned char* data, int size, int* width, int* height, int* channels);
FloatImage loadHdr(const unsigned char* data, int size);
std::string failureReason();
}  // namespace hp::stb
