// The structural similarity index (Wang, Bovik, Sheikh & Simoncelli 2004)
// with the paper's defaults: both images on the 0-255 scale (rounded to
// levels, as a PNG holds them), an 11x11 Gaussian window of sigma 1.5,
// K1 = 0.01, K2 = 0.03, L = 255; the mean over every window that lies inside
// the image. 1 for identical images.
#pragma once

#include "aapat/render/renderer.h"

namespace aapat {

constexpr int kSsimWindow = 11;  // images smaller than this in either side have no SSIM

double ssim(const Image& image, const Image& reference);

}  // namespace aapat
