#include "samples/tools/image_compare.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/luminance.h"
#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "shaders/shared/tonemap.h"

namespace hp {
namespace {
constexpr int kHalfWindow = 3;  // 7x7

double displayValue(float linear, float exposure) {
  const double c = gpu::tonemapFilmic(linear * exposure);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double luminance(const LinearImage& im, std::uint32_t x, std::uint32_t y, bool display, float exposure) {
  glm::dvec3 rgb;
  for (std::uint32_t c = 0; c < 3; ++c) rgb[int(c)] = display ? displayValue(im.at(x, y, c), exposure) : im.at(x, y, c);
  return luminanceOf(rgb);
}

std::vector<double> displayLuminance(const LinearImage& im, float exposure) {
  std::vector<double> out(std::size_t(im.width) * im.height);
  for (std::uint32_t y = 0; y < im.height; ++y)
    for (std::uint32_t x = 0; x < im.width; ++x) out[std::size_t(y) * im.width + x] = luminance(im, x, y, true, exposure);
  return out;
}

double ssimAt(const std::vector<double>& a, const std::vector<double>& b, std::uint32_t w, std::uint32_t h, int cx,
              int cy) {
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
  for (int y = std::max(0, cy - kHalfWindow); y <= std::min(int(h) - 1, cy + kHalfWindow); ++y)
    for (int x = std::max(0, cx - kHalfWindow); x <= std::min(int(w) - 1, cx + kHalfWindow); ++x) {
      const double va = a[std::size_t(y) * w + x], vb = b[std::size_t(y) * w + x];
      sa += va, sb += vb, saa += va * va, sbb += vb * vb, sab += va * vb, n += 1;
    }
  const double ma = sa / n, mb = sb / n;
  const double va = saa / n - ma * ma, vb = sbb / n - mb * mb, cov = sab / n - ma * mb;
  const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  return ((2 * ma * mb + c1) * (2 * cov + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
}

// Every value must be finite: one NaN made the error NaN, which was reported as 99 dB. Small negative
// values are kept (real-time frames hold a few, -5e-4, from rounding in the shading).
void checkFinite(const LinearImage& im, const char* which) {
  for (std::size_t i = 0; i < im.values.size(); ++i)
    if (!std::isfinite(im.values[i])) {
      const std::size_t pixel = i / im.channels;
      throw Error(std::string("compare: the ") + which + " has a non-finite value at pixel (" +
                  std::to_string(pixel % im.width) + ", " + std::to_string(pixel / im.width) + "), channel " +
                  std::to_string(i % im.channels));
    }
}

// Each metric must come out finite: a value past what the display curve can take (~1e19 with the
// exposure) overflows it.
double finiteMetric(double value, const char* name) {
  if (!std::isfinite(value))
    throw Error(std::string("compare: the ") + name + " came out non-finite (a radiance too large for the display curve?)");
  return value;
}
}  // namespace

ImageComparison compareImages(const LinearImage& image, const LinearImage& reference, const LinearImage& mask,
                              float exposure) {
  if (!(std::isfinite(exposure) && exposure > 0.0f))
    throw Error("compare: exposure must be finite and > 0, got " + numberText(exposure));
  if (image.channels != 3 || reference.channels != 3) throw Error("compare: both images must be RGB");
  if (image.width != reference.width || image.height != reference.height)
    throw Error("compare: the images differ in size (" + std::to_string(image.width) + "x" + std::to_string(image.height) +
                " vs " + std::to_string(reference.width) + "x" + std::to_string(reference.height) + ")");
  const bool masked = mask.width > 0;
  if (masked && (mask.channels != 1 || mask.width != image.width || mask.height != image.height))
    throw Error("compare: the mask must be one channel of the images' size");
  checkFinite(image, "image");
  checkFinite(reference, "reference");
  const std::vector<double> la = displayLuminance(image, exposure), lb = displayLuminance(reference, exposure);
  ImageComparison r;
  double se = 0, ssim = 0, lumA = 0, lumB = 0, red[2] = {0, 0}, blue[2] = {0, 0};
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x) {
      if (masked && !(mask.at(x, y, 0) > 0.5f)) continue;
      ++r.pixels;
      for (std::uint32_t c = 0; c < 3; ++c) {
        const double d = displayValue(image.at(x, y, c), exposure) - displayValue(reference.at(x, y, c), exposure);
        se += d * d;
      }
      ssim += ssimAt(la, lb, image.width, image.height, int(x), int(y));
      lumA += luminance(image, x, y, false, exposure);
      lumB += luminance(reference, x, y, false, exposure);
      red[0] += image.at(x, y, 0), blue[0] += image.at(x, y, 2);
      red[1] += reference.at(x, y, 0), blue[1] += reference.at(x, y, 2);
    }
  if (r.pixels == 0) throw Error("compare: the mask selects no pixel");
  const double mse = finiteMetric(se / (3.0 * double(r.pixels)), "mean squared error");
  r.psnrDb = mse > 0.0 ? 10.0 * std::log10(1.0 / mse) : 99.0;  // identical display values: 99 dB
  r.ssim = finiteMetric(ssim / double(r.pixels), "SSIM");
  r.luminanceRatio = finiteMetric(lumB > 0.0 ? lumA / lumB : 0.0, "luminance ratio");
  r.redBlueImage = blue[0] > 0.0 ? red[0] / blue[0] : 0.0;
  r.redBlueReference = blue[1] > 0.0 ? red[1] / blue[1] : 0.0;
  return r;
}
}  // namespace hp
