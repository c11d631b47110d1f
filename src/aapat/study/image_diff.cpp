#include "aapat/study/image_diff.h"

#include <cmath>

#include "aapat/render/ssim.h"

namespace aapat {
namespace {

// The grey mean of the channels, as the renderer's images hold values.
Image grey_of(const ColorImage& c) {
  Image g{c.width, c.height, 0, std::vector<double>(c.pixels())};
  for (size_t p = 0; p < c.pixels(); ++p)
    g.values[p] = (c.rgb[3 * p] + c.rgb[3 * p + 1] + c.rgb[3 * p + 2]) / 3.0;
  return g;
}

}  // namespace

ImageDiff image_diff(const ColorImage& reference, const ColorImage& test, double ppd) {
  ImageDiff d;
  d.ppd = ppd;
  d.flip = flip(reference, test, ppd);  // checks the sizes and ppd first
  double sum = 0;
  for (size_t k = 0; k < reference.rgb.size(); ++k) {
    const double e = 255.0 * (static_cast<double>(test.rgb[k]) - reference.rgb[k]);
    sum += e * e;
  }
  d.rmse = std::sqrt(sum / static_cast<double>(reference.rgb.size()));
  if (d.rmse > 0) d.psnr = 20 * std::log10(255 / d.rmse);
  if (reference.width >= kSsimWindow && reference.height >= kSsimWindow)
    d.ssim = ssim(grey_of(test), grey_of(reference));
  return d;
}

}  // namespace aapat
