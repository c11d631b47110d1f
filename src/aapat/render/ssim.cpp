#include "aapat/render/ssim.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

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

// Output rows per band of the windowed means: the band's row-filtered
// values are its rows plus the window's height, a few hundred KB, reused,
// where five full-size planes of doubles per channel (a 1920x1080 diff
// touched 480 MB) cost more in page faults than in arithmetic.
constexpr int kBandRows = 32;

// The sum of the SSIM index over output rows [j0, j1) of one channel, where
// x(i, j) and y(i, j) are the two images' levels: the Gaussian-weighted
// means of x, y, x^2, y^2 and xy over each window inside the image
// (separable: rows, then columns), then the index per window.
template <class X, class Y>
double band_ssim_sum(int w, int j0, int j1, X x, Y y) {
  static const auto g = gaussian_window();
  const int vw = w - kSsimWindow + 1, rows = j1 - j0 + kSsimWindow - 1;
  std::vector<double> r(static_cast<size_t>(5) * rows * vw);
  double* rx = r.data();
  double* ry = rx + static_cast<size_t>(rows) * vw;
  double* rxx = ry + static_cast<size_t>(rows) * vw;
  double* ryy = rxx + static_cast<size_t>(rows) * vw;
  double* rxy = ryy + static_cast<size_t>(rows) * vw;
  for (int jj = 0; jj < rows; ++jj)
    for (int i = 0; i < vw; ++i) {
      double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
      for (int k = 0; k < kSsimWindow; ++k) {
        const double a = x(i + k, j0 + jj), b = y(i + k, j0 + jj);
        sx += g[k] * a, sy += g[k] * b, sxx += g[k] * (a * a), syy += g[k] * (b * b),
            sxy += g[k] * (a * b);
      }
      const size_t o = static_cast<size_t>(jj) * vw + i;
      rx[o] = sx, ry[o] = sy, rxx[o] = sxx, ryy[o] = syy, rxy[o] = sxy;
    }
  double sum = 0;
  for (int j = 0; j < j1 - j0; ++j) {
    double row_sum = 0;
    for (int i = 0; i < vw; ++i) {
      double mx = 0, my = 0, mxx = 0, myy = 0, mxy = 0;
      for (int k = 0; k < kSsimWindow; ++k) {
        const size_t o = static_cast<size_t>(j + k) * vw + i;
        mx += g[k] * rx[o], my += g[k] * ry[o], mxx += g[k] * rxx[o], myy += g[k] * ryy[o],
            mxy += g[k] * rxy[o];
      }
      const double vx = mxx - mx * mx, vy = myy - my * my, cxy = mxy - mx * my;
      row_sum +=
          (2 * mx * my + kC1) * (2 * cxy + kC2) / ((mx * mx + my * my + kC1) * (vx + vy + kC2));
    }
    sum += row_sum;
  }
  return sum;
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
  // (Bytes: levels are 0 to 255, and an eighth of the memory of doubles.)
  std::vector<unsigned char> la(a.values.size()), lb(b.values.size());
  tbb::parallel_for(size_t{0}, la.size(), [&](size_t k) {
    la[k] = static_cast<unsigned char>(grey_level(a.values[k]));
    lb[k] = static_cast<unsigned char>(grey_level(b.values[k]));
  });
  // A colour image's SSIM is the mean of its channels' (scikit-image's channel_axis).
  const auto n = static_cast<size_t>(a.channels);
  const int w = a.width, h = a.height, vh = h - kSsimWindow + 1;
  const int bands = (vh + kBandRows - 1) / kBandRows;
  double total = 0;
  for (size_t c = 0; c < n; ++c) {
    auto x = [&](int i, int j) {
      return static_cast<double>(la[(static_cast<size_t>(j) * a.width + i) * n + c]);
    };
    auto y = [&](int i, int j) {
      return static_cast<double>(lb[(static_cast<size_t>(j) * b.width + i) * n + c]);
    };
    // Bands in parallel, their sums added in order: the same value on any
    // number of threads.
    std::vector<double> band_sums(static_cast<size_t>(bands));
    tbb::parallel_for(0, bands, [&](int band) {
      const int j0 = band * kBandRows;
      band_sums[static_cast<size_t>(band)] =
          band_ssim_sum(w, j0, std::min(vh, j0 + kBandRows), x, y);
    });
    double sum = 0;
    for (double v : band_sums) sum += v;
    total += sum / (static_cast<double>(w - kSsimWindow + 1) * vh);
  }
  return total / static_cast<double>(n);
}

}  // namespace aapat
