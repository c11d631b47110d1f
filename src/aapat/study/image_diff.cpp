#include "aapat/study/image_diff.h"

#include <cmath>

#include "aapat/render/image_error.h"
#include "aapat/render/ssim.h"

namespace aapat {
namespace {

bool is_grey(const ColorImage& c) {
  for (size_t k = 0; k < c.rgb.size(); k += 3)
    if (c.rgb[k] != c.rgb[k + 1] || c.rgb[k] != c.rgb[k + 2]) return false;
  return true;
}

// The file's colours as a rendering holds them, so that RMSE and SSIM are
// the renderer's: three channels (SSIM the mean of the channels'), or one
// when both images are grey (R = G = B), as a grey rendering is, so that a
// grey pair scores to the last digit what `render` scores. Rows bottom-up,
// as the renderer's are (a file's run from the top), so that every sum runs
// in the renderer's order.
Image image_of(const ColorImage& c, bool grey) {
  const int channels = grey ? 1 : 3;
  std::vector<double> v(static_cast<size_t>(c.width) * c.height * channels);
  for (int j = 0; j < c.height; ++j)
    for (int i = 0; i < c.width; ++i)
      for (int ch = 0; ch < channels; ++ch)
        v[(static_cast<size_t>(c.height - 1 - j) * c.width + i) * channels + ch] =
            c.rgb[3 * (static_cast<size_t>(j) * c.width + i) + ch];
  return {c.width, c.height, 0, std::move(v), channels};
}

}  // namespace

ImageDiff image_diff(const ColorImage& reference, const ColorImage& test, double ppd) {
  ImageDiff d;
  d.ppd = ppd;
  d.flip = flip(reference, test, ppd);  // checks the sizes and ppd first
  // The renderer's RMSE (render/image_error.h), the same arithmetic: on the
  // files' 8-bit levels, over every channel.
  const bool grey = is_grey(test) && is_grey(reference);
  const Image a = image_of(test, grey), b = image_of(reference, grey);
  d.rmse = compare(a, b).rmse;
  if (d.rmse > 0) d.psnr = 20 * std::log10(255 / d.rmse);
  if (reference.width >= kSsimWindow && reference.height >= kSsimWindow) d.ssim = ssim(a, b);
  return d;
}

}  // namespace aapat
