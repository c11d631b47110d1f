// Double-double numbers: an unevaluated sum hi + lo of two doubles, about 106
// bits of significand (Dekker; Knuth's TwoSum; TwoProd). Sums of
// millions of terms near 0.1 whose difference is 1e-8 (the L2-star
// discrepancy) keep about 1e-30 of absolute accuracy, where one double keeps
// 1e-17 per term and loses the result.
#pragma once

#include <cmath>

namespace aapat {

struct DoubleDouble {
  double hi = 0, lo = 0;

  constexpr DoubleDouble() = default;
  constexpr DoubleDouble(double v) : hi(v), lo(0) {}  // NOLINT: a double is exact here
  constexpr DoubleDouble(double h, double l) : hi(h), lo(l) {}
  double value() const { return hi + lo; }
};

// a + b exactly, as a double-double (Knuth's TwoSum).
inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// a * b exactly, as a double-double. With a hardware FMA the error is one
// fma; without one (baseline x86-64), std::fma is a library call that costs
// more than the rest of the sum, so Dekker's split computes the same exact
// error inline: each half has at most 27 bits, so every partial product is
// exact (and stays so if the compiler contracts it into an FMA). |a|, |b|
// below 2^995, far above any value here.
inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
#if defined(__FMA__) || defined(__aarch64__)
  return {p, std::fma(a, b, -p)};
#else
  constexpr double kSplit = 134217729.0;  // 2^27 + 1
  const double ta = kSplit * a, tb = kSplit * b;
  const double ah = ta - (ta - a), al = a - ah, bh = tb - (tb - b), bl = b - bh;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
#endif
}

inline DoubleDouble renormalized(double hi, double lo) {
  const double s = hi + lo;
  return {s, lo - (s - hi)};
}

inline DoubleDouble operator+(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble s = two_sum(a.hi, b.hi), t = two_sum(a.lo, b.lo);
  const DoubleDouble u = renormalized(s.hi, s.lo + t.hi);
  return renormalized(u.hi, u.lo + t.lo);
}

inline DoubleDouble operator-(DoubleDouble a) {
  return {-a.hi, -a.lo};
}

inline DoubleDouble operator-(DoubleDouble a, DoubleDouble b) {
  return a + (-b);
}

inline DoubleDouble operator*(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble p = two_prod(a.hi, b.hi);
  return renormalized(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

inline DoubleDouble operator/(DoubleDouble a, double b) {
  const double q1 = a.hi / b;
  const DoubleDouble r = a - two_prod(q1, b);
  const double q2 = r.hi / b;
  const DoubleDouble r2 = r - two_prod(q2, b);
  return renormalized(q1, q2) + DoubleDouble(r2.hi / b);
}

inline DoubleDouble& operator+=(DoubleDouble& a, DoubleDouble b) {
  return a = a + b;
}

}  // namespace aapat
