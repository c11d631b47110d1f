#include "aapat/temporal/engine/rendered_flicker.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace aapat {

double rendered_flicker(const std::vector<int>& error, const std::vector<int>& previous, int width,
                        int height, int channels, const Motion& motion, const Scene& now,
                        const Scene& before) {
  if (!motion.moving()) {
    double change = 0;
    for (size_t i = 0; i < error.size(); ++i) change += std::abs(error[i] - previous[i]);
    return error.empty() ? 0 : change / static_cast<double>(error.size());
  }
  const auto at = [&](int i, int j, int c) {
    i = std::clamp(i, 0, width - 1);
    j = std::clamp(j, 0, height - 1);
    return static_cast<double>(
        previous[(static_cast<size_t>(j) * width + i) * static_cast<size_t>(channels) + c]);
  };
  double change = 0;
  size_t counted = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Vec2 q = previous_point(motion, now, before, {double(x), double(y)});
      if (!on_image(q, width, height)) continue;
      const double fx = std::floor(q.x), fy = std::floor(q.y), tx = q.x - fx, ty = q.y - fy;
      const int i = static_cast<int>(fx), j = static_cast<int>(fy);
      for (int c = 0; c < channels; ++c) {
        const double before = (1 - ty) * ((1 - tx) * at(i, j, c) + tx * at(i + 1, j, c)) +
                              ty * ((1 - tx) * at(i, j + 1, c) + tx * at(i + 1, j + 1, c));
        change += std::abs(error[(static_cast<size_t>(y) * width + x) * channels + c] - before);
        ++counted;
      }
    }
  return counted ? change / static_cast<double>(counted) : 0;
}

}  // namespace aapat
