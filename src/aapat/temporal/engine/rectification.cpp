#include "aapat/temporal/engine/rectification.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"

namespace aapat {

Rectification parse_rectification(std::string_view name) {
  if (name == "none") return Rectification::none;
  if (name == "clamp") return Rectification::clamp;
  if (name == "clip") return Rectification::clip;
  throw Error(fmt::format("unknown rectification '{}': known are none, clamp, clip", name));
}

std::string_view rectification_name(Rectification r) {
  return r == Rectification::none ? "none" : r == Rectification::clamp ? "clamp" : "clip";
}

RectificationBox parse_rectification_box(std::string_view name) {
  if (name == "minmax") return RectificationBox::minmax;
  if (name == "variance") return RectificationBox::variance;
  throw Error(fmt::format("unknown rectification box '{}': known are minmax, variance", name));
}

std::string_view rectification_box_name(RectificationBox b) {
  return b == RectificationBox::minmax ? "minmax" : "variance";
}

void rgb_to_ycocg(const double* c, double* o) {
  o[0] = 0.25 * c[0] + 0.5 * c[1] + 0.25 * c[2];
  o[1] = 0.5 * c[0] - 0.5 * c[2];
  o[2] = -0.25 * c[0] + 0.5 * c[1] - 0.25 * c[2];
}

void ycocg_to_rgb(const double* c, double* o) {
  o[0] = c[0] + c[1] - c[2];
  o[1] = c[0] + c[2];
  o[2] = c[0] - c[1] - c[2];
}

void rectify(Rectification r, RectificationBox box, double gamma, const double* nb, int n,
             double* history) {
  if (r == Rectification::none) return;
  double lo[3], hi[3];
  for (int c = 0; c < n; ++c) {
    if (box == RectificationBox::minmax) {
      lo[c] = hi[c] = nb[c];
      for (int k = 1; k < 9; ++k) {
        lo[c] = std::min(lo[c], nb[k * n + c]);
        hi[c] = std::max(hi[c], nb[k * n + c]);
      }
    } else {
      double m1 = 0, m2 = 0;
      for (int k = 0; k < 9; ++k) {
        m1 += nb[k * n + c];
        m2 += nb[k * n + c] * nb[k * n + c];
      }
      m1 /= 9;
      const double sigma = std::sqrt(std::max(0.0, m2 / 9 - m1 * m1));
      lo[c] = m1 - gamma * sigma;
      hi[c] = m1 + gamma * sigma;
    }
  }
  if (r == Rectification::clamp) {
    for (int c = 0; c < n; ++c) history[c] = std::clamp(history[c], lo[c], hi[c]);
    return;
  }
  // Clip toward the centre: scale the offset by its largest ratio to the half-extent.
  double largest = 0;
  for (int c = 0; c < n; ++c) {
    const double centre = 0.5 * (lo[c] + hi[c]), extent = 0.5 * (hi[c] - lo[c]) + 1e-8;
    largest = std::max(largest, std::abs(history[c] - centre) / extent);
  }
  if (largest <= 1) return;
  for (int c = 0; c < n; ++c) {
    const double centre = 0.5 * (lo[c] + hi[c]);
    history[c] = centre + (history[c] - centre) / largest;
  }
}

}  // namespace aapat
