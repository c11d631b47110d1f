#include "aapat/core/polynomial.h"

#include <algorithm>
#include <cmath>

#include "aapat/core/geometry.h"

namespace aapat {

Polynomial operator+(const Polynomial& a, const Polynomial& b) {
  Polynomial r{std::vector<double>(std::max(a.c.size(), b.c.size()), 0.0)};
  for (size_t k = 0; k < a.c.size(); ++k) r.c[k] += a.c[k];
  for (size_t k = 0; k < b.c.size(); ++k) r.c[k] += b.c[k];
  return r;
}

Polynomial operator*(const Polynomial& a, const Polynomial& b) {
  if (a.c.empty() || b.c.empty()) return {};
  Polynomial r{std::vector<double>(a.c.size() + b.c.size() - 1, 0.0)};
  for (size_t i = 0; i < a.c.size(); ++i)
    for (size_t j = 0; j < b.c.size(); ++j) r.c[i + j] += a.c[i] * b.c[j];
  return r;
}

Polynomial operator*(double s, const Polynomial& a) {
  Polynomial r = a;
  for (double& v : r.c) v *= s;
  return r;
}

Polynomial constant(double v) {
  return Polynomial{{v}};
}

Polynomial antiderivative(const Polynomial& p) {
  Polynomial r{std::vector<double>(p.c.size() + 1, 0.0)};
  for (size_t k = 0; k < p.c.size(); ++k) r.c[k + 1] = p.c[k] / static_cast<double>(k + 1);
  r.c[0] = -r(-1.0);
  return r;
}

std::vector<double> chebyshev_nodes(int degree) {
  std::vector<double> t(degree + 1);
  for (int j = 0; j <= degree; ++j) t[j] = std::cos(kPi * (j + 0.5) / (degree + 1));
  return t;
}

Polynomial chebyshev_interpolant_from_values(const std::vector<double>& values) {
  const int n = static_cast<int>(values.size());
  // Chebyshev coefficients by the discrete cosine transform at the nodes.
  std::vector<double> a(n, 0.0);
  for (int k = 0; k < n; ++k) {
    double s = 0;
    for (int j = 0; j < n; ++j) s += values[j] * std::cos(kPi * k * (j + 0.5) / n);
    a[k] = (k == 0 ? 1.0 : 2.0) * s / n;
  }
  // Sum a_k T_k(t) in the monomial basis, T_{k+1} = 2t T_k - T_{k-1}.
  Polynomial result{std::vector<double>(n, 0.0)};
  Polynomial t_prev{{1.0}}, t_cur{{0.0, 1.0}};
  const Polynomial two_t{{0.0, 2.0}};
  for (int k = 0; k < n; ++k) {
    const Polynomial& tk = k == 0 ? t_prev : t_cur;
    for (size_t i = 0; i < tk.c.size(); ++i) result.c[i] += a[k] * tk.c[i];
    if (k >= 1) {
      Polynomial next = two_t * t_cur + (-1.0) * t_prev;
      t_prev = t_cur;
      t_cur = next;
    }
  }
  return result;
}

}  // namespace aapat
