#include "samples/tools/radiance_hdr.h"

#include <array>
#include <cmath>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

// Reads the bytes of one picture, front to back, refusing to run past their end.
class ByteReader {
 public:
  ByteReader(std::span<const std::byte> bytes, const std::string& source) : bytes_(bytes), source_(source) {}
  std::uint8_t next() {
    if (at_ >= bytes_.size()) fail("truncated: the pixels end early");
    return std::uint8_t(bytes_[at_++]);
  }
  // The next line without its '\n'; the header's lines only.
  std::string line() {
    std::string out;
    for (;;) {
      if (at_ >= bytes_.size() || at_ >= kMaxHeaderBytes) fail("no end to the header");
      const char c = char(bytes_[at_++]);
      if (c == '\n') return out;
      out.push_back(c);
    }
  }
  std::size_t remaining() const { return bytes_.size() - at_; }
  [[noreturn]] void fail(const std::string& why) const { throw Error(source_ + ": " + why); }

 private:
  std::span<const std::byte> bytes_;
  std::size_t at_ = 0;
  const std::string& source_;
};

void readHeader(ByteReader& in) {
  const std::string magic = in.line();
  if (magic.rfind("#?RADIANCE", 0) != 0 && magic.rfind("#?RGBE", 0) != 0)
    in.fail("not a Radiance .hdr image (it does not start with #?RADIANCE)");
  for (std::string l = in.line(); !l.empty(); l = in.line())
    if (l.rfind("FORMAT=", 0) == 0 && l != "FORMAT=32-bit_rle_rgbe")
      in.fail("the pixel format '" + excerpt(l.substr(7)) + "' is not 32-bit_rle_rgbe");
}

void readSize(ByteReader& in, std::uint64_t maxTexels, std::uint32_t& width, std::uint32_t& height) {
  const std::string l = in.line();
  std::istringstream s(l);
  std::string ya, xa;
  long long h = 0, w = 0;
  if (!(s >> ya >> h >> xa >> w) || ya != "-Y" || xa != "+X")
    in.fail("the orientation '" + excerpt(l) + "' is not the standard -Y H +X W");
  if (w < 1 || h < 1 || w > (1ll << 30) || h > (1ll << 30) || std::uint64_t(w) * std::uint64_t(h) > maxTexels)
    in.fail("an image of " + std::to_string(w) + "x" + std::to_string(h) + " texels is empty or larger than the " +
            std::to_string(maxTexels) + " texels allowed");
  width = std::uint32_t(w);
  height = std::uint32_t(h);
}

// The fewest bytes a scanline of `width` can take: run-length coded (where readScanline allows it), its 4-byte
// start and per channel one run of up to 127 texels per 2 bytes; else 4 bytes a texel.
std::uint64_t smallestScanline(std::uint32_t width) {
  if (width >= 8 && width < 32768) return 4 + 4 * 2 * ((std::uint64_t(width) + 126) / 127);
  return 4 * std::uint64_t(width);
}

// One scanline of RGBE quadruples into `row` (4 x width bytes).
void readScanline(ByteReader& in, std::uint32_t width, std::vector<std::uint8_t>& row) {
  std::array<std::uint8_t, 4> first{};
  for (auto& b : first) b = in.next();
  const bool runLength = width >= 8 && width < 32768 && first[0] == 2 && first[1] == 2 && (first[2] & 0x80) == 0;
  if (!runLength) {
    std::copy(first.begin(), first.end(), row.begin());
    for (std::size_t i = 4; i < row.size(); ++i) row[i] = in.next();
    return;
  }
  if ((std::uint32_t(first[2]) << 8 | first[3]) != width) in.fail("a run-length scanline of another width");
  for (std::uint32_t channel = 0; channel < 4; ++channel)
    for (std::uint32_t x = 0; x < width;) {
      const std::uint8_t code = in.next();
      const std::uint32_t count = code > 128 ? code - 128u : code;
      if (count == 0 || x + count > width) in.fail("a run of " + std::to_string(count) + " past its scanline");
      if (code > 128) {
        const std::uint8_t value = in.next();
        for (std::uint32_t k = 0; k < count; ++k) row[4 * (x + k) + channel] = value;
      } else {
        for (std::uint32_t k = 0; k < count; ++k) row[4 * (x + k) + channel] = in.next();
      }
      x += count;
    }
}
}  // namespace

RgbFloatImage decodeRadianceHdr(std::span<const std::byte> bytes, std::uint64_t maxTexels, const std::string& source) {
  ByteReader in(bytes, source);
  readHeader(in);
  RgbFloatImage image;
  readSize(in, maxTexels, image.width, image.height);
  // A header may claim any size within maxTexels: the file must be able to hold it before the image is made.
  if (smallestScanline(image.width) * image.height > in.remaining())
    in.fail("truncated: " + std::to_string(in.remaining()) + " bytes cannot hold " + std::to_string(image.height) +
            " scanlines of " + std::to_string(image.width) + " texels");
  image.rgb.resize(std::size_t(image.width) * image.height * 3);
  std::vector<std::uint8_t> row(std::size_t(image.width) * 4);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    readScanline(in, image.width, row);
    float* out = image.rgb.data() + std::size_t(y) * image.width * 3;
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* p = &row[4 * x];
      const float scale = p[3] == 0 ? 0.0f : std::ldexp(1.0f, int(p[3]) - 136);  // mantissa / 256 x 2^(e - 128)
      for (int c = 0; c < 3; ++c) out[3 * x + c] = float(p[c]) * scale;
    }
  }
  return image;
}
}  // namespace hp
