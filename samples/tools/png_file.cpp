#include "samples/tools/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
constexpr std::uint32_t kMaxPngSide = 16384;  // the largest frame the tools render

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  const auto* bytes = reinterpret_cast<const std::byte*>(data);
  out->insert(out->end(), bytes, bytes + size);
}
}  // namespace

std::vector<std::byte> encodePng(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                 std::span<const std::uint8_t> pixels) {
  if (channels != 3 && channels != 4) throw Error("encodePng: 3 or 4 channels, got " + std::to_string(channels));
  if (width == 0 || height == 0 || pixels.size() != std::size_t(width) * height * channels)
    throw Error("encodePng: pixel data does not match " + std::to_string(width) + "x" + std::to_string(height));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw Error("libpng: cannot create a PNG writer");
  }
  std::vector<std::byte> out;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("libpng: PNG encoding failed");
  }
  png_set_write_fn(png, &out, appendBytes, nullptr);
  png_set_IHDR(png, info, width, height, 8, channels == 4 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (std::uint32_t y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(pixels.data() + std::size_t(y) * width * channels));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

void writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height, std::uint32_t channels,
              std::span<const std::uint8_t> pixels) {
  writeFileAtomically(path, encodePng(width, height, channels, pixels));
}

RgbaImage readPngRgba(const std::filesystem::path& path) {
  // Through the bounded door (a regular file, under the size limit), then decoded from memory; the
  // declared size is checked before the pixels are allocated.
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxImageFileBytes);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw Error(path.string() + ": cannot read PNG: " + image.message);
  if (image.width < 1 || image.height < 1 || image.width > kMaxPngSide || image.height > kMaxPngSide) {
    png_image_free(&image);
    throw Error(path.string() + ": PNG size " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " is outside [1, " + std::to_string(kMaxPngSide) + "] per side");
  }
  image.format = PNG_FORMAT_RGBA;
  RgbaImage out;
  out.width = image.width;
  out.height = image.height;
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.pixels.data(), 0, nullptr)) {
    png_image_free(&image);
    throw Error(path.string() + ": cannot decode PNG: " + image.message);
  }
  return out;
}
}  // namespace hp
