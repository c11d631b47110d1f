#include "aapat/study/image_diff.h"

#include <cmath>

#include "aapat/render/image_error.h"
#include "aapat/render/ssim.h"

namespace aapat {
namespace {

// The file's colours as a three-channel rendering holds them, so that SSIM
// is the renderer's (the mean of the channels' SSIMs; a grey file's R = G = B
// gives its grey SSIM).
Image image_of(const ColorImage& c) {
  return {c.width, c.height, 0, std::vector<double>(c.rgb.begin(), c.rgb.end()), 3};
}

}  // namespace

ImageDiff image_diff(const ColorImage& reference, const ColorImage& test, double ppd) {
  ImageDiff d;
  d.ppd = ppd;
  d.flip = flip(reference, test, ppd);  // checks the sizes and ppd first
  // The renderer's RMSE (render/image_error.h), the same arithmetic: on the
  // files' 8-bit levels, over every channel.
  const Image a = image_of(test), b = image_of(reference);
  d.rmse = compare(a, b).rmse;
  if (d.rmse > 0) d.psnr = 20 * std::log10(255 / d.rmse);
  if (reference.width >= kSsimWindow && reference.height >= kSsimWindow) d.ssim = ssim(a, b);
  return d;
}

}  // namespace aapat
