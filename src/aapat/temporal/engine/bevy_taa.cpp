#include "aapat/temporal/engine/bevy_taa.h"

#include <algorithm>

#include "aapat/temporal/engine/rectification.h"

namespace aapat {

BevyPixel bevy_taa_pixel(const std::array<BevyColour, 9>& n, const BevyColour* history,
                         double confidence, bool still) {
  const BevyColour& current = n[4];
  if (!history) return {current, 1};  // off screen: weight 1, confidence 1
  BevyPixel out;
  out.confidence = still ? confidence + 10 : 1;
  const double alpha =
      std::clamp(1 / out.confidence, kBevyMinHistoryBlendRate, kBevyDefaultHistoryBlendRate);
  // clip_towards_aabb_center to mean +- one deviation of the 3x3 in YCoCg:
  // the generic pipeline's clip to the variance box at gamma 1.
  double nb[27], hy[3];
  for (size_t k = 0; k < 9; ++k) rgb_to_ycocg(n[k].data(), &nb[k * 3]);
  rgb_to_ycocg(history->data(), hy);
  rectify(Rectification::clip, RectificationBox::variance, 1, nb, 3, hy);
  BevyColour h;
  ycocg_to_rgb(hy, h.data());
  for (double& v : h) v = std::clamp(v, 0.0, 1.0);  // YCoCg_to_RGB saturates
  for (size_t c = 0; c < 3; ++c) out.rgb[c] = h[c] + alpha * (current[c] - h[c]);
  return out;
}

BevyPixel bevy_reset_pixel(const BevyColour& sample) {
  return {sample, 1 / kBevyMinHistoryBlendRate};
}

}  // namespace aapat
