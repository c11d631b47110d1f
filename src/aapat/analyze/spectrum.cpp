#include "aapat/analyze/spectrum.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <tuple>

#include "aapat/analyze/spectrum_simd.h"
#include "aapat/core/interrupt.h"

namespace aapat {

Spectrum2D power_spectrum(const std::vector<Vec2>& points, int size) {
  const size_t n = points.size(), m = static_cast<size_t>(size);
  const int half = size / 2;
  // exp(-2 pi i v y_j) for every point and row frequency v, computed once.
  std::vector<double> ey_re(n * m), ey_im(n * m);
  tbb::parallel_for(size_t{0}, n, [&](size_t j) {
    for (size_t k = 0; k < m; ++k) {
      const double angle = -2 * kPi * (static_cast<double>(k) - half) * points[j].y;
      ey_re[j * m + k] = std::cos(angle);
      ey_im[j * m + k] = std::sin(angle);
    }
  });
  Spectrum2D s{size, std::vector<double>(m * m)};
  // Column u of the output: sum_j exp(-2 pi i u x_j) exp(-2 pi i v y_j) over
  // v, for u <= 0 only. The points are real, so P(-u, -v) = P(u, v): the
  // columns u > 0 are the mirror of those (bit for bit: cos is even and sin
  // odd, so the mirrored sums are the same products), all but the row whose
  // mirror -v lies outside the grid (v = -size/2 for an even size), summed
  // directly.
  const size_t computed = static_cast<size_t>(half) + 1;  // columns u = -half .. 0
  auto column_term = [&](size_t j, double u) {
    return std::pair{std::cos(-2 * kPi * u * points[j].x), std::sin(-2 * kPi * u * points[j].x)};
  };
  // Blocks of kBlock columns: each point's row of exp(-2 pi i v y) is read
  // once per block instead of once per column (the table is n x size, far
  // larger than the caches); each column's sums are as before, term by term.
  constexpr size_t kBlock = 8;
  const size_t columns = std::min(computed, m);
  tbb::parallel_for(size_t{0}, (columns + kBlock - 1) / kBlock, [&](size_t block) {
    throw_if_interrupted();
    const size_t first = block * kBlock, count = std::min(kBlock, columns - first);
    std::vector<double> re(kBlock * m, 0.0), im(kBlock * m, 0.0);
    double ar[kPointsAtOnce * kBlock], ai[kPointsAtOnce * kBlock];
    for (size_t j = 0; j < n; j += kPointsAtOnce) {
      const size_t points = std::min(kPointsAtOnce, n - j);
      for (size_t q = 0; q < points; ++q)
        for (size_t c = 0; c < count; ++c)
          std::tie(ar[q * count + c], ai[q * count + c]) =
              column_term(j + q, static_cast<double>(first + c) - half);
      add_points_to_columns(points, ar, ai, count, &ey_re[j * m], &ey_im[j * m], m, m, re.data(),
                            im.data());
    }
    for (size_t c = 0; c < count; ++c)
      for (size_t v = 0; v < m; ++v)
        s.power[v * m + first + c] =
            (re[c * m + v] * re[c * m + v] + im[c * m + v] * im[c * m + v]) / n;
  });
  tbb::parallel_for(computed, m, [&](size_t col) {
    const size_t mirror_col = 2 * static_cast<size_t>(half) - col;
    for (size_t row = 0; row < m; ++row) {
      const size_t mirror_row = 2 * static_cast<size_t>(half) - row;  // wraps past m for row 0
      if (mirror_row < m) {
        s.power[row * m + col] = s.power[mirror_row * m + mirror_col];
        continue;
      }
      double re = 0, im = 0;
      for (size_t j = 0; j < n; ++j) {
        const auto [ar, ai] = column_term(j, static_cast<double>(col) - half);
        re += ar * ey_re[j * m + row] - ai * ey_im[j * m + row];
        im += ar * ey_im[j * m + row] + ai * ey_re[j * m + row];
      }
      s.power[row * m + col] = (re * re + im * im) / n;
    }
  });
  return s;
}

std::vector<uint8_t> spectrum_grey_pixels(const Spectrum2D& s) {
  const size_t m = static_cast<size_t>(s.size);
  std::vector<uint8_t> pixels(m * m);
  for (size_t row = 0; row < m; ++row)
    for (size_t col = 0; col < m; ++col) {
      const double p = s.power[(m - 1 - row) * m + col];
      pixels[row * m + col] = static_cast<uint8_t>(std::lround(255 * std::min(1.0, p / 2)));
    }
  return pixels;
}

void accumulate(Spectrum2D& sum, const Spectrum2D& other, double weight) {
  if (sum.size == 0) sum = Spectrum2D{other.size, std::vector<double>(other.power.size(), 0.0)};
  for (size_t i = 0; i < other.power.size(); ++i) sum.power[i] += weight * other.power[i];
}

RadialProfile radial_average(const Spectrum2D& s) {
  const int half = s.size / 2;
  std::vector<double> sum(half + 1, 0.0), sum_sq(half + 1, 0.0), count(half + 1, 0.0);
  for (int v = -half; v < s.size - half; ++v)
    for (int u = -half; u < s.size - half; ++u) {
      const int r = static_cast<int>(std::lround(std::hypot(u, v)));
      if (r > half) continue;  // rings cut by the square's edge are left out
      const double p = s.at(u, v);
      sum[r] += p;
      sum_sq[r] += p * p;
      count[r] += 1;
    }
  RadialProfile out;
  for (int r = 0; r <= half; ++r) {
    if (count[r] == 0) continue;
    const double mean = sum[r] / count[r];
    const double var = std::max(0.0, sum_sq[r] / count[r] - mean * mean);
    out.radius.push_back(r);
    out.power.push_back(mean);
    out.anisotropy_db.push_back(mean > 0 && var > 0 ? 10 * std::log10(var / (mean * mean))
                                                    : -INFINITY);
  }
  return out;
}

std::vector<double> power_spectrum_1d(const std::vector<double>& xs, int count, double f_max) {
  std::vector<double> power(count);
  const double df = f_max / count;
  constexpr int kBlock = 256;  // exact exponentials at each block start, rotations inside
  tbb::parallel_for(0, (count + kBlock - 1) / kBlock, [&](int b) {
    throw_if_interrupted();
    const int k0 = b * kBlock, k1 = std::min(count, k0 + kBlock);
    std::vector<std::complex<double>> sum(k1 - k0);
    for (double x : xs) {
      std::complex<double> z = std::polar(1.0, -2 * kPi * k0 * df * x);
      const std::complex<double> step = std::polar(1.0, -2 * kPi * df * x);
      for (int k = k0; k < k1; ++k, z *= step) sum[k - k0] += z;
    }
    for (int k = k0; k < k1; ++k) power[k] = std::norm(sum[k - k0]) / xs.size();
  });
  return power;
}

}  // namespace aapat
