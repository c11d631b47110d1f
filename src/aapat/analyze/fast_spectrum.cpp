#include "aapat/analyze/fast_spectrum.h"

#include "aapat/core/interrupt.h"

#include <fftw3.h>
#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>

namespace aapat {
namespace {

// The Gaussian's parameters for M frequencies per axis (the header's terms).
struct Gridding {
  int m = 0, r = 0, w = kSpreadHalfWidth;  // frequencies, grid points per axis, half-width
  double h = 0, tau = 0;

  explicit Gridding(int size) : m(size), r(2 * size), h(1.0 / (2 * size)) {
    tau = w / (8 * std::sqrt(2.0) * kPi * double(m) * m);
  }
  // The Gaussian's transform at frequency k: sqrt(4 pi tau) exp(-4 pi^2 k^2 tau).
  double transform(double k) const {
    return std::sqrt(4 * kPi * tau) * std::exp(-4 * kPi * kPi * k * k * tau);
  }
};

// One coordinate's spread: the grid index of the window's first point and
// the Gaussian at the window's 2w points, exp(-(l h - d)^2 / (4 tau)) for
// l = -w+1 .. w, d the coordinate's offset past its grid point, by the
// product exp(-d^2/4tau) exp(l h d/2tau) exp(-(l h)^2/4tau) (Greengard-Lee's
// fast gridding: three exponentials per coordinate, not 2w).
struct Window {
  int first = 0;  // grid index of l = -w+1 (may be negative: it wraps)
  double weight[2 * kSpreadHalfWidth];
};

Window window(const Gridding& g, double coordinate, const double* square_terms) {
  const double t = (coordinate - std::floor(coordinate)) * g.r;
  int base = static_cast<int>(std::floor(t));
  if (base >= g.r) base = g.r - 1;  // t rounded up to r
  const double d = (t - base) * g.h;
  Window win;
  win.first = base - g.w + 1;
  const double e1 = std::exp(-d * d / (4 * g.tau)), step = std::exp(g.h * d / (2 * g.tau));
  // l = 0 .. w upward, l = -1 .. -w+1 downward, from exp(-d^2/4tau).
  double up = e1, down = e1;
  for (int l = 0; l <= g.w; ++l, up *= step) win.weight[l + g.w - 1] = up * square_terms[l];
  for (int l = 1; l < g.w; ++l) {
    down /= step;
    win.weight[g.w - 1 - l] = down * square_terms[l];
  }
  return win;
}

// FFTW's planner is not thread-safe; plans are made one at a time.
std::mutex& planner_lock() {
  static std::mutex lock;
  return lock;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

}  // namespace

FastSpectrum power_spectrum_fast(const std::vector<Vec2>& points, int size) {
  if (size < kMinSpectrumSize || size > kMaxSpectrumSize || size % 2 != 0)
    throw Error(fmt::format("fast spectrum: size {} must be even, {} to {}", size, kMinSpectrumSize,
                            kMaxSpectrumSize));
  const Gridding g(size);
  const size_t n = points.size(), r = static_cast<size_t>(g.r);
  // exp(-(l h)^2 / (4 tau)), l = 0 .. w.
  std::vector<double> square_terms(g.w + 1);
  for (int l = 0; l <= g.w; ++l) square_terms[l] = std::exp(-(l * g.h) * (l * g.h) / (4 * g.tau));

  // Spread: the grid in bands of rows, each band summing the points whose
  // window reaches it in the order (window's first row, point index), which
  // no band boundary or thread count changes.
  std::unique_ptr<double, FftwFree> grid(static_cast<double*>(fftw_malloc(sizeof(double) * r * r)));
  std::unique_ptr<fftw_complex, FftwFree> spectrum(
      static_cast<fftw_complex*>(fftw_malloc(sizeof(fftw_complex) * r * (r / 2 + 1))));
  if (!grid || !spectrum) throw Error(fmt::format("fast spectrum: no memory for a {}^2 grid", r));
  std::fill(grid.get(), grid.get() + r * r, 0.0);
  std::vector<std::vector<size_t>> by_first_row(r);
  for (size_t j = 0; j < n; ++j) {
    const int first = window(g, points[j].y, square_terms.data()).first;
    by_first_row[static_cast<size_t>((first % g.r + g.r) % g.r)].push_back(j);
  }
  constexpr size_t kBand = 16;
  tbb::parallel_for(size_t{0}, (r + kBand - 1) / kBand, [&](size_t band) {
    throw_if_interrupted();
    const int lo = static_cast<int>(band * kBand), hi = static_cast<int>(std::min(r, lo + kBand));
    // Windows starting 2w-1 rows below the band reach into it.
    for (int start = lo - 2 * g.w + 1; start < hi; ++start) {
      for (const size_t j : by_first_row[static_cast<size_t>((start % g.r + g.r) % g.r)]) {
        const Window wy = window(g, points[j].y, square_terms.data());
        const Window wx = window(g, points[j].x, square_terms.data());
        for (int l = 0; l < 2 * g.w; ++l) {
          const int row = start + l;
          if (row < lo || row >= hi) continue;
          double* out = grid.get() + static_cast<size_t>(row) * r;
          for (int c = 0; c < 2 * g.w; ++c) {
            const int col = ((wx.first + c) % g.r + g.r) % g.r;
            out[col] += wy.weight[l] * wx.weight[c];
          }
        }
      }
    }
  });

  {
    fftw_plan plan;
    {
      std::lock_guard<std::mutex> lock(planner_lock());
      plan = fftw_plan_dft_r2c_2d(g.r, g.r, grid.get(), spectrum.get(), FFTW_ESTIMATE);
    }
    fftw_execute(plan);
    std::lock_guard<std::mutex> lock(planner_lock());
    fftw_destroy_plan(plan);
  }

  // Divide by the Gaussian's transform: F(k) = D(k) / (r^2 G(kx) G(ky)).
  const int half = size / 2;
  std::vector<double> undo(static_cast<size_t>(size));  // 1 / (r G(k)), k = -half ..
  for (int k = -half; k < size - half; ++k) undo[k + half] = 1.0 / (g.r * g.transform(k));
  FastSpectrum out;
  out.spectrum = Spectrum2D{size, std::vector<double>(static_cast<size_t>(size) * size)};
  const double count = static_cast<double>(std::max<size_t>(n, 1));
  double largest_sum = 0;
  for (int v = -half; v < size - half; ++v)
    for (int u = -half; u < size - half; ++u) {
      // r2c keeps kx >= 0; D(-k) is the conjugate of D(k), of the same size.
      const int kx = u >= 0 ? u : -u, ky = u >= 0 ? v : -v;
      const fftw_complex& d =
          spectrum.get()[static_cast<size_t>((ky % g.r + g.r) % g.r) * (r / 2 + 1) + kx];
      const double scale = undo[u + half] * undo[v + half];
      const double re = d[0] * scale, im = d[1] * scale;
      double magnitude_sq = re * re + im * im;
      if (u == 0 && v == 0)
        magnitude_sq = count * count;  // F(0) = N exactly
      else
        largest_sum = std::max(largest_sum, std::sqrt(magnitude_sq));
      out.spectrum.power[static_cast<size_t>(v + half) * size + (u + half)] = magnitude_sq / count;
    }

  // The error bound (header): aliasing, the Gaussian left out of each window,
  // and rounding, each divided by the transform where it is smallest (k = M/2).
  auto alias = [&](double k) {
    double a = 0;
    for (int p = -3; p <= 3; ++p)
      if (p != 0) a += std::exp(-4 * kPi * kPi * g.tau * ((k + p * g.r) * (k + p * g.r) - k * k));
    return a;
  };
  const double a = alias(half);
  const double gaussian_sum = std::sqrt(4 * kPi * g.tau) / g.h + 1;  // per axis, at most
  const double q = std::exp(-2 * g.w * g.h * g.h / (4 * g.tau));
  const double left_out = 2 * square_terms[g.w] / (1 - q);  // per axis, past w on both sides
  const double u_round = std::numeric_limits<double>::epsilon() / 2;
  const double rounding =
      u_round * (5 * std::log2(double(r) * r) + 4 * g.w) * gaussian_sum * gaussian_sum;
  const double amplify = undo[0] * undo[0];  // 1 / (r^2 G(M/2)^2), the largest
  out.sum_error = (1 + a) * (1 + a) - 1 + (2 * gaussian_sum * left_out + rounding) * amplify;
  const double e = count * out.sum_error;
  out.error_bound = (2 * largest_sum * e + e * e) / count;
  return out;
}

}  // namespace aapat
