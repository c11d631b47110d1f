// `aapat diff` and `aapat.diff`: how a test image differs from its
// reference, by the classic measures on the 8-bit scale (RMSE and PSNR over
// the three channels, SSIM of the grey mean of the channels) and by FLIP,
// the perceived difference (analyze/flip.h).
#pragma once

#include <optional>

#include "aapat/analyze/flip.h"

namespace aapat {

struct ImageDiff {
  double ppd = 0;
  double rmse = 0;             // levels of 255, over R, G and B
  std::optional<double> psnr;  // dB; none when the images are equal
  std::optional<double> ssim;  // none below an SSIM window (11 pixels) a side
  FlipResult flip;
};

ImageDiff image_diff(const ColorImage& reference, const ColorImage& test, double ppd);

}  // namespace aapat
