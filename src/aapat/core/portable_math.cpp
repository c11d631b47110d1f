#include "aapat/core/portable_math.h"

#include <array>
#include <cmath>
#include <limits>

// Double-double arithmetic needs each product and sum rounded on its own:
// this file is compiled with -ffp-contract=off (CMakeLists.txt), so that no
// compiler fuses a*b+c into one rounding on a machine with FMA.
namespace aapat {
namespace {

struct DD {
  double hi, lo;
};

DD two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DD quick_two_sum(double a, double b) {  // |a| >= |b|
  const double s = a + b;
  return {s, b - (s - a)};
}
// Dekker's split and product: a*b = p + e exactly.
DD two_prod(double a, double b) {
  constexpr double kSplit = 134217729.0;  // 2^27 + 1
  const double ta = kSplit * a, ah = ta - (ta - a), al = a - ah;
  const double tb = kSplit * b, bh = tb - (tb - b), bl = b - bh;
  const double p = a * b;
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}
DD add(DD a, DD b) {
  DD s = two_sum(a.hi, b.hi);
  const DD t = two_sum(a.lo, b.lo);
  s = quick_two_sum(s.hi, s.lo + t.hi);
  return quick_two_sum(s.hi, s.lo + t.lo);
}
DD neg(DD a) {
  return {-a.hi, -a.lo};
}
DD mul(DD a, DD b) {
  const DD p = two_prod(a.hi, b.hi);
  return quick_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
DD mul(DD a, double b) {
  const DD p = two_prod(a.hi, b);
  return quick_two_sum(p.hi, p.lo + a.lo * b);
}
DD div(DD a, double b) {
  const double q1 = a.hi / b;
  const DD p = two_prod(q1, b);
  const double r = ((a.hi - p.hi) - p.lo) + a.lo;
  return quick_two_sum(q1, r / b);
}
DD div(DD a, DD b) {
  const double q1 = a.hi / b.hi;
  const DD r = add(a, neg(mul(b, q1)));
  const double q2 = r.hi / b.hi;
  const DD r2 = add(r, neg(mul(b, q2)));
  return add(two_sum(q1, q2), DD{r2.hi / b.hi, 0});
}

// pi/2 and log 2 as three doubles each (their sums to about 2^-160).
constexpr double kHalfPi[3] = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54,
                               -0x1.f1976b7ed8fbcp-110};
constexpr double kLog2[3] = {0x1.62e42fefa39efp-1, 0x1.abc9e3b39803fp-56, 0x1.7b57a079a1934p-111};
constexpr double kTiny = 0x1p-110;  // a series stops when its terms fall below this, relatively

// x - k c for c given in three parts, in double-double.
DD reduce(DD x, double k, const double (&c)[3]) {
  DD r = add(x, neg(two_prod(k, c[0])));
  r = add(r, neg(two_prod(k, c[1])));
  return add(r, DD{-k * c[2], 0});
}

// sin r and cos r for |r| <= pi/4 by their Taylor series.
DD sin_series(DD r) {
  const DD r2 = mul(r, r);
  DD term = r, sum = r;
  for (int i = 1; i < 40 && std::abs(term.hi) > kTiny * std::abs(sum.hi); ++i) {
    term = neg(div(mul(term, r2), double(2 * i) * double(2 * i + 1)));
    sum = add(sum, term);
  }
  return sum;
}
DD cos_series(DD r) {
  const DD r2 = mul(r, r);
  DD term{1, 0}, sum{1, 0};
  for (int i = 1; i < 40 && std::abs(term.hi) > kTiny; ++i) {
    term = neg(div(mul(term, r2), double(2 * i - 1) * double(2 * i)));
    sum = add(sum, term);
  }
  return sum;
}

// The quadrant q (0..3) of x and x less q pi/2.
DD quadrant(double x, int& q) {
  const double k = std::nearbyint(x * 0x1.45f306dc9c883p-1);  // x * 2/pi
  const double m = std::fmod(k, 4.0);
  q = static_cast<int>(m < 0 ? m + 4 : m);
  return reduce(DD{x, 0}, k, kHalfPi);
}

// e^x for a double-double x, before overflow and underflow are handled.
DD exp_dd(DD x, int& scale) {
  const double k = std::nearbyint(x.hi * 0x1.71547652b82fep+0);  // x / log 2
  scale = static_cast<int>(k);
  const DD r = reduce(x, k, kLog2);  // |r| <= log 2 / 2
  DD term{1, 0}, sum{1, 0};
  for (int i = 1; i < 60 && std::abs(term.hi) > kTiny; ++i) {
    term = div(mul(term, r), double(i));
    sum = add(sum, term);
  }
  return sum;
}

DD log_dd(double x) {
  int e = 0;
  double m = std::frexp(x, &e);    // x = m 2^e, m in [1/2, 1): exact
  if (m < 0x1.6a09e667f3bcdp-1) {  // below sqrt(1/2): m in [sqrt(1/2), sqrt(2))
    m *= 2;
    --e;
  }
  // log m = 2 atanh(s), s = (m - 1)/(m + 1), |s| < 0.172.
  const DD s = div(DD{m - 1, 0}, two_sum(m, 1));  // m - 1 is exact here
  const DD s2 = mul(s, s);
  DD power = s, sum = s;
  for (int i = 1; i < 60 && std::abs(power.hi) > kTiny * std::abs(sum.hi); ++i) {
    power = mul(power, s2);
    sum = add(sum, div(power, double(2 * i + 1)));
  }
  const double ed = e;
  return add(mul(sum, 2.0),
             add(two_prod(ed, kLog2[0]), add(two_prod(ed, kLog2[1]), DD{ed * kLog2[2], 0})));
}

double scaled(DD v, int scale) {
  // 2^scale (hi + lo) rounded once where it is normal; two ldexp steps so
  // that 2^scale itself never overflows on the way.
  const double r = v.hi + v.lo;
  const int half = scale / 2;
  return std::ldexp(std::ldexp(r, half), scale - half);
}

}  // namespace

double portable_sin(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0) return x;  // keeps the sign of zero
  int q = 0;
  const DD r = quadrant(x, q);
  const DD v = q == 0   ? sin_series(r)
               : q == 1 ? cos_series(r)
               : q == 2 ? neg(sin_series(r))
                        : neg(cos_series(r));
  return v.hi + v.lo;
}

double portable_cos(double x) {
  if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
  int q = 0;
  const DD r = quadrant(x, q);
  const DD v = q == 0   ? cos_series(r)
               : q == 1 ? neg(sin_series(r))
               : q == 2 ? neg(cos_series(r))
                        : sin_series(r);
  return v.hi + v.lo;
}

double portable_exp(double x) {
  if (std::isnan(x)) return x;
  if (x > 709.8) return std::numeric_limits<double>::infinity();
  if (x < -745.2) return 0.0;
  int scale = 0;
  const DD v = exp_dd(DD{x, 0}, scale);
  return scaled(v, scale);
}

double portable_log(double x) {
  if (std::isnan(x) || x < 0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0) return -std::numeric_limits<double>::infinity();
  if (std::isinf(x)) return x;
  const DD v = log_dd(x);
  return v.hi + v.lo;
}

double portable_exp_fast(double x) {
  if (std::isnan(x)) return x;
  if (x > 709.78) return std::numeric_limits<double>::infinity();
  if (x < -745.1) return 0.0;
  const double k = std::nearbyint(x * 0x1.71547652b82fep+0);
  // x - k log 2 in two parts (Cody and Waite): k log2_hi is exact for |k| < 2^20.
  const double r = (x - k * 0x1.62e42fee00000p-1) - k * 0x1.a39ef35793c76p-33;
  // 1/n! for n = 0..13, each the correctly rounded quotient of two exact
  // doubles, made at compile time; |r| <= 0.347, so r^14/14! is below 2^-66.
  static constexpr auto kInvFactorial = [] {
    std::array<double, 14> f{};
    double n_factorial = 1;
    for (int n = 0; n < 14; ++n) {
      if (n > 0) n_factorial *= n;
      f[static_cast<size_t>(n)] = 1.0 / n_factorial;
    }
    return f;
  }();
  double p = kInvFactorial[13];
  for (int n = 12; n >= 0; --n) p = p * r + kInvFactorial[static_cast<size_t>(n)];
  const int e = static_cast<int>(k), half = e / 2;
  return std::ldexp(std::ldexp(p, half), e - half);
}

double portable_log_fast(double x) {
  if (std::isnan(x) || x < 0) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0) return -std::numeric_limits<double>::infinity();
  if (std::isinf(x)) return x;
  int e = 0;
  double m = std::frexp(x, &e);
  if (m < 0x1.6a09e667f3bcdp-1) {
    m *= 2;
    --e;
  }
  const double s = (m - 1) / (m + 1), s2 = s * s;  // |s| < 0.172
  double p = 1.0 / 23;
  for (int n = 21; n >= 1; n -= 2) p = p * s2 + 1.0 / n;
  return 2 * s * p + e * 0x1.62e42fefa39efp-1;
}

double portable_pow(double x, double y) {
  if (y == 0) return 1.0;
  if (std::isnan(x) || std::isnan(y)) return std::numeric_limits<double>::quiet_NaN();
  if (x == 0) return y > 0 ? 0.0 : std::numeric_limits<double>::infinity();
  if (x < 0) {
    if (y != std::nearbyint(y)) return std::numeric_limits<double>::quiet_NaN();
    const double odd = std::fmod(y, 2.0) != 0 ? -1.0 : 1.0;
    return odd * portable_pow(-x, y);
  }
  if (x == 1) return 1.0;
  const DD l = mul(log_dd(x), y);
  if (l.hi > 709.8) return std::numeric_limits<double>::infinity();
  if (l.hi < -745.2) return 0.0;
  int scale = 0;
  const DD v = exp_dd(l, scale);
  return scaled(v, scale);
}

}  // namespace aapat
