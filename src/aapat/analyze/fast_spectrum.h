// The 2D power spectrum by a non-uniform FFT: the fast mode for many points
// at many frequencies, where the exact sum (spectrum.h) costs N M^2.
//
// Gaussian gridding (after Greengard & Lee 2004), all in the unit-period
// convention of spectrum.h: each point spreads a periodized Gaussian
// exp(-|x|^2 / (4 tau)) onto a 2M x 2M grid (M frequencies per axis, 2x
// oversampling) over its nearest 2w x 2w grid points; FFTW transforms the
// grid; each frequency k is divided by the Gaussian's transform
// G(k) = sqrt(4 pi tau) exp(-4 pi^2 k^2 tau). With tau = w / (8 sqrt(2) pi M^2)
// the two errors balance: the aliases k + 2M p are damped by
// G(k + 2M p) / G(k) <= exp(-8 pi^2 tau M^2) = exp(-pi w / sqrt 2), and the
// Gaussian left out past w grid points weighs exp(-(w / 2M)^2 / (4 tau)),
// the same. O(N w^2 + M^2 log M) instead of O(N M^2).
//
// The error bound is computed from those terms for the size asked (not an
// asymptotic rate): |F_fast(k) - F(k)| <= N eps for the sum F(k) =
// sum_j exp(-2 pi i k . p_j), so that
//   |P_fast(k) - P(k)| <= (2 |F_fast(k)| N eps + (N eps)^2) / N,
// reported as its largest value over k != 0 (P(0) = N is set exactly).
// w = 14 gives eps near 1e-10 at M = 1024, most of it the rounding estimate
// (u (5 log2 r^2 + 4w) per unit of spread mass) amplified by the division.
#pragma once

#include <vector>

#include "aapat/analyze/spectrum.h"
#include "aapat/core/geometry.h"

namespace aapat {

struct FastSpectrum {
  Spectrum2D spectrum;
  double error_bound = 0;  // on |P_fast(k) - P(k)|, the largest over k != 0
  double sum_error = 0;    // eps: on |F_fast(k) - F(k)| / N
};

// Grid points each point spreads to on each side of it, per axis.
inline constexpr int kSpreadHalfWidth = 14;

// The same frequencies as power_spectrum (size M: -M/2 .. M/2-1 per axis).
// Deterministic for any thread count (each grid row sums its points in
// index order; FFTW's plan is made with FFTW_ESTIMATE, one thread).
FastSpectrum power_spectrum_fast(const std::vector<Vec2>& points, int size);

}  // namespace aapat
