#include "aapat/render/ssim.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "aapat/render/image_error.h"

namespace aapat {
namespace {

constexpr double kSigma = 1.5, kL = 255, kC1 = (0.01 * kL) * (0.01 * kL),
                 kC2 = (0.03 * kL) * (0.03 * kL);

std::array<double, kSsimWindow> gaussian_window() {
  std::array<double, kSsimWindow> g{};
  double sum = 0;
  for (int k = 0; k < kSsimWindow; ++k) {
    const double d = k - kSsimWindow / 2;
    g[k] = std::exp(-d * d / (2 * kSigma * kSigma));
    sum += g[k];
  }
  for (double& v : g) v /= sum;  // the 2D window is g x g, normalized to 1
  return g;
}

// The Gaussian-weighted mean of f over every window inside the image
// (separable: rows, then columns); (w - 10) x (h - 10) values.
template <class F>
std::vector<double> window_means(int w, int h, F f) {
  static const auto g = gaussian_window();
  const int vw = w - kSsimWindow + 1, vh = h - kSsimWindow + 1;
  std::vector<double> rows(static_cast<size_t>(vw) * h), out(static_cast<size_t>(vw) * vh);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < vw; ++i) {
      double s = 0;
      for (int k = 0; k < kSsimWindow; ++k) s += g[k] * f(i + k, j);
      rows[static_cast<size_t>(j) * vw + i] = s;
    }
  for (int j = 0; j < vh; ++j)
    for (int i = 0; i < vw; ++i) {
      double s = 0;
      for (int k = 0; k < kSsimWindow; ++k) s += g[k] * rows[static_cast<size_t>(j + k) * vw + i];
      out[static_cast<size_t>(j) * vw + i] = s;
    }
  return out;
}

}  // namespace

double ssim(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(fmt::format("ssim: a {}x{} image of {} channel(s) against a {}x{} reference of {}",
                            a.width, a.height, a.channels, b.width, b.height, b.channels));
  if (a.width < kSsimWindow || a.height < kSsimWindow)
    throw Error(fmt::format("ssim: a {}x{} image is smaller than the {}x{} window", a.width,
                            a.height, kSsimWindow, kSsimWindow));
  // Both images as levels once, not once per window tap of each of the five means.
  std::vector<double> la(a.values.size()), lb(b.values.size());
  for (size_t k = 0; k < la.size(); ++k) {
    la[k] = grey_level(a.values[k]);
    lb[k] = grey_level(b.values[k]);
  }
  // A colour image's SSIM is the mean of its channels' (scikit-image's channel_axis).
  const auto n = static_cast<size_t>(a.channels);
  double total = 0;
  for (size_t c = 0; c < n; ++c) {
    auto x = [&](int i, int j) { return la[(static_cast<size_t>(j) * a.width + i) * n + c]; };
    auto y = [&](int i, int j) { return lb[(static_cast<size_t>(j) * b.width + i) * n + c]; };
    const int w = a.width, h = a.height;
    const auto mx = window_means(w, h, x), my = window_means(w, h, y);
    const auto mxx = window_means(w, h, [&](int i, int j) { return x(i, j) * x(i, j); });
    const auto myy = window_means(w, h, [&](int i, int j) { return y(i, j) * y(i, j); });
    const auto mxy = window_means(w, h, [&](int i, int j) { return x(i, j) * y(i, j); });
    double sum = 0;
    for (size_t k = 0; k < mx.size(); ++k) {
      const double vx = mxx[k] - mx[k] * mx[k], vy = myy[k] - my[k] * my[k],
                   cxy = mxy[k] - mx[k] * my[k];
      sum += (2 * mx[k] * my[k] + kC1) * (2 * cxy + kC2) /
             ((mx[k] * mx[k] + my[k] * my[k] + kC1) * (vx + vy + kC2));
    }
    total += sum / static_cast<double>(mx.size());
  }
  return total / static_cast<double>(n);
}

}  // namespace aapat
