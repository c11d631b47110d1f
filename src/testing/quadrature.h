// Adaptive Simpson quadrature for tests: an independent way to integrate the
// filters, so the exact tables can be checked against their definitions.
#pragma once

#include <cmath>

namespace aapat::testing {

template <class F>
double adaptive_simpson_step(F& f, double a, double b, double fa, double fm, double fb,
                             double whole, double tol, int depth) {
  const double m = (a + b) / 2, lm = (a + m) / 2, rm = (m + b) / 2;
  const double flm = f(lm), frm = f(rm);
  const double left = (m - a) / 6 * (fa + 4 * flm + fm);
  const double right = (b - m) / 6 * (fm + 4 * frm + fb);
  if (depth <= 0 || std::abs(left + right - whole) <= 15 * tol)
    return left + right + (left + right - whole) / 15;
  return adaptive_simpson_step(f, a, m, fa, flm, fm, left, tol / 2, depth - 1) +
         adaptive_simpson_step(f, m, b, fm, frm, fb, right, tol / 2, depth - 1);
}

// Integral of f over [a, b] to about `tol`; split at kinks for best results.
template <class F>
double integrate(F f, double a, double b, double tol = 1e-13) {
  if (b <= a) return 0;
  const double fa = f(a), fb = f(b), fm = f((a + b) / 2);
  return adaptive_simpson_step(f, a, b, fa, fm, fb, (b - a) / 6 * (fa + 4 * fm + fb), tol, 40);
}

// Integral over [a, b] split at every multiple of `piece` so that kinks at
// the filters' breakpoints (0, 1, the radius) fall on piece boundaries.
template <class F>
double integrate_pieces(F f, double a, double b, double piece = 0.25) {
  double total = 0;
  double lo = a;
  while (lo < b) {
    const double hi = std::min(b, (std::floor(lo / piece + 1e-12) + 1) * piece);
    total += integrate(f, lo, hi);
    lo = hi;
  }
  return total;
}

}  // namespace aapat::testing
