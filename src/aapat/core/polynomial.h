// Polynomials in a segment-local variable t in [-1, 1], used to tabulate a
// filter piece by piece so that its step response and the integrals the metric
// needs are exact polynomial antiderivatives (never sums over small steps).
#pragma once

#include <vector>

namespace aapat {

struct Polynomial {
  std::vector<double> c;  // c[k] multiplies t^k

  double operator()(double t) const {
    double r = 0;
    for (auto k = c.size(); k-- > 0;) r = r * t + c[k];
    return r;
  }
};

Polynomial operator+(const Polynomial& a, const Polynomial& b);
Polynomial operator*(const Polynomial& a, const Polynomial& b);
Polynomial operator*(double s, const Polynomial& a);
Polynomial constant(double v);

// Antiderivative P with P(-1) = 0.
Polynomial antiderivative(const Polynomial& p);

// Interpolates f on [-1, 1] at degree+1 Chebyshev points; exact (to rounding)
// when f is a polynomial of at most that degree.
template <class F>
Polynomial chebyshev_interpolant(F&& f, int degree);

Polynomial chebyshev_interpolant_from_values(const std::vector<double>& values_at_nodes);
std::vector<double> chebyshev_nodes(int degree);

template <class F>
Polynomial chebyshev_interpolant(F&& f, int degree) {
  std::vector<double> values;
  for (double t : chebyshev_nodes(degree)) values.push_back(f(t));
  return chebyshev_interpolant_from_values(values);
}

}  // namespace aapat
