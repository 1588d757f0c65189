#pragma once
// Contract: how close an image is to a reference over a mask (the real-time frame against
// `hairpipe reference`, docs/SHADING.md). Both are linear RGB radiance of the same size; the mask
// (1 channel, same size) selects pixels with value > 0.5 (empty mask: every pixel).
//  - psnrDb: over the selected pixels and the 3 channels, on display values in [0, 1] (exposure, the
//    filmic curve, the sRGB transfer function; unquantised): 10 log10(1 / MSE);
//  - ssim: mean SSIM of the display luminance over 7x7 windows centred on selected pixels (uniform
//    window, C1 = 0.01^2, C2 = 0.03^2; windows are clipped at the border);
//  - luminanceRatio: mean linear luminance (Rec. 709 weights) of the image / that of the reference;
//  - redBlueImage/redBlueReference: mean red / mean blue (the hue of the hair).
// Identical display values give psnrDb 99. Throws hp::Error when the sizes differ, a channel count is
// wrong, no pixel is selected, the exposure is not finite and > 0, a value of either image is not finite
// (naming the pixel), or a metric comes out non-finite (a value too large or negative for the display curve).
#include <cstdint>

#include "samples/tools/linear_image.h"

namespace hp {
struct ImageComparison {
  double psnrDb = 0.0;
  double ssim = 0.0;
  double luminanceRatio = 0.0;
  double redBlueImage = 0.0, redBlueReference = 0.0;
  std::uint64_t pixels = 0;  // selected
};

ImageComparison compareImages(const LinearImage& image, const LinearImage& reference, const LinearImage& mask,
                              float exposure);
}  // namespace hp
