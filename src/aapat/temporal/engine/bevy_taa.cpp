#include "aapat/temporal/engine/bevy_taa.h"

#include <algorithm>
#include <cmath>

#include "aapat/temporal/engine/rectification.h"

namespace aapat {

BevyPixel bevy_taa_pixel(const std::array<BevyColour, 9>& n, const BevyColour* history,
                         double confidence, bool still) {
  const BevyColour& current = n[4];
  BevyPixel out;
  out.confidence = still ? confidence + 10 : 1;
  double alpha =
      std::clamp(1 / out.confidence, kBevyMinHistoryBlendRate, kBevyDefaultHistoryBlendRate);
  if (!history) {
    alpha = 1;
    out.confidence = 1;
  }
  BevyColour h{};
  if (history) {
    // The 3x3's mean and standard deviation in YCoCg; the history clipped toward the box centre.
    double m1[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
    for (const BevyColour& s : n) {
      double y[3];
      rgb_to_ycocg(s.data(), y);
      for (int c = 0; c < 3; ++c) {
        m1[c] += y[c];
        m2[c] += y[c] * y[c];
      }
    }
    double lo[3], hi[3], hy[3];
    for (int c = 0; c < 3; ++c) {
      const double mean = m1[c] / 9, sigma = std::sqrt(std::max(m2[c] / 9 - mean * mean, 0.0));
      lo[c] = mean - sigma;
      hi[c] = mean + sigma;
    }
    rgb_to_ycocg(history->data(), hy);
    double largest = 0, centre[3];
    for (int c = 0; c < 3; ++c) {
      centre[c] = 0.5 * (hi[c] + lo[c]);
      largest = std::max(largest, std::abs((hy[c] - centre[c]) / (0.5 * (hi[c] - lo[c]) + 1e-8)));
    }
    if (largest > 1)
      for (int c = 0; c < 3; ++c) hy[c] = centre[c] + (hy[c] - centre[c]) / largest;
    ycocg_to_rgb(hy, h.data());
    for (double& v : h) v = std::clamp(v, 0.0, 1.0);  // YCoCg_to_RGB saturates
  }
  for (size_t c = 0; c < 3; ++c) out.rgb[c] = h[c] + alpha * (current[c] - h[c]);
  return out;
}

BevyPixel bevy_reset_pixel(const BevyColour& sample) {
  return {sample, 1 / kBevyMinHistoryBlendRate};
}

}  // namespace aapat
