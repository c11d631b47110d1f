#include "aapat/analyze/discrepancy.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace aapat {

double l2_star_discrepancy(const std::vector<Vec2>& p) {
  // Warnock 1972: T^2 = 1/9 - (2/N) sum_i prod_k (1 - x_ik^2)/2
  //                     + (1/N^2) sum_i sum_j prod_k (1 - max(x_ik, x_jk)).
  check_discrepancy_size(p.size());
  const double n = static_cast<double>(p.size());
  double single = 0, pairs = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    single += (1 - p[i].x * p[i].x) * (1 - p[i].y * p[i].y) / 4;
    for (size_t j = 0; j < p.size(); ++j)
      pairs += (1 - std::max(p[i].x, p[j].x)) * (1 - std::max(p[i].y, p[j].y));
  }
  return std::sqrt(std::max(0.0, 1.0 / 9 - 2 * single / n + pairs / (n * n)));
}

namespace {

// Largest deviation over anchored boxes whose corners take the given x and
// y values, counting points strictly inside (x < a, y < b) and on or inside.
double boxes_deviation(const std::vector<Vec2>& p, const std::vector<double>& xs,
                       const std::vector<double>& ys) {
  std::vector<size_t> by_x(p.size());
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](size_t a, size_t b) { return p[a].x < p[b].x; });
  const double n = static_cast<double>(p.size());
  std::vector<double> open_y, closed_y;  // y of the points left of a, kept sorted
  size_t next_open = 0, next_closed = 0;
  double worst = 0;
  for (double a : xs) {
    auto insert = [&](std::vector<double>& v, double y) {
      v.insert(std::upper_bound(v.begin(), v.end(), y), y);
    };
    while (next_open < by_x.size() && p[by_x[next_open]].x < a)
      insert(open_y, p[by_x[next_open++]].y);
    while (next_closed < by_x.size() && p[by_x[next_closed]].x <= a)
      insert(closed_y, p[by_x[next_closed++]].y);
    for (double b : ys) {
      const double inside = std::lower_bound(open_y.begin(), open_y.end(), b) - open_y.begin();
      const double with_border =
          std::upper_bound(closed_y.begin(), closed_y.end(), b) - closed_y.begin();
      worst = std::max({worst, a * b - inside / n, with_border / n - a * b});
    }
  }
  return worst;
}

}  // namespace

StarDiscrepancy star_discrepancy(const std::vector<Vec2>& p, size_t exact_limit, int grid) {
  StarDiscrepancy d;
  if (p.size() <= exact_limit) {
    std::vector<double> xs{1.0}, ys{1.0};
    for (const Vec2& v : p) xs.push_back(v.x), ys.push_back(v.y);
    std::sort(xs.begin(), xs.end());
    std::sort(ys.begin(), ys.end());
    d.lower = d.upper = boxes_deviation(p, xs, ys);
    d.exact = true;
    return d;
  }
  // A box between grid lines holds at least the points of the smaller grid
  // box and at most those of the larger: the deviation is bounded by the
  // worse of the two mixed comparisons (upper), and the grid boxes give a lower bound.
  std::vector<double> g(grid + 1);
  for (int i = 0; i <= grid; ++i) g[i] = static_cast<double>(i) / grid;
  std::vector<int> counts((grid + 1) * (grid + 1), 0);  // points with x < g[i], y < g[j]
  for (const Vec2& v : p) {
    const int i = std::min(grid, static_cast<int>(std::floor(v.x * grid)) + 1);
    const int j = std::min(grid, static_cast<int>(std::floor(v.y * grid)) + 1);
    ++counts[i * (grid + 1) + j];
  }
  for (int i = 0; i <= grid; ++i)
    for (int j = 0; j <= grid; ++j) {
      int& c = counts[i * (grid + 1) + j];
      if (i > 0) c += counts[(i - 1) * (grid + 1) + j];
      if (j > 0) c += counts[i * (grid + 1) + j - 1];
      if (i > 0 && j > 0) c -= counts[(i - 1) * (grid + 1) + j - 1];
    }
  const double n = static_cast<double>(p.size());
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const double lo = counts[i * (grid + 1) + j] / n;
      const double hi = counts[(i + 1) * (grid + 1) + j + 1] / n;
      d.upper = std::max({d.upper, hi - g[i] * g[j], g[i + 1] * g[j + 1] - lo});
      d.lower = std::max(d.lower,
                         std::abs(g[i + 1] * g[j + 1] - counts[(i + 1) * (grid + 1) + j + 1] / n));
    }
  return d;
}

double half_plane_area(double phi, double t) {
  // Clip the unit square by p . n <= t (Sutherland-Hodgman, one plane) and
  // take the polygon's area.
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Vec2 out[8];
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = square[i], b = square[(i + 1) % 4];
    const double da = a.x * c + a.y * s - t, db = b.x * c + b.y * s - t;
    if (da <= 0) out[m++] = a;
    if ((da < 0) != (db < 0) && da != db) {
      const double u = da / (da - db);
      out[m++] = {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)};
    }
  }
  double area = 0;
  for (int i = 0; i < m; ++i) area += out[i].x * out[(i + 1) % m].y - out[(i + 1) % m].x * out[i].y;
  return std::abs(area) / 2;
}

void check_discrepancy_size(size_t points) {
  if (points > kMaxDiscrepancyPoints)
    throw Error(fmt::format(
        "discrepancy: {} points exceed the limit of {} (the L2-star sum is O(N^2) today)", points,
        kMaxDiscrepancyPoints));
}

EdgeDiscrepancy edge_discrepancy(const std::vector<Vec2>& p, int directions,
                                 const std::function<void(int, int)>& progress) {
  check_discrepancy_size(p.size());
  EdgeDiscrepancy d;
  const double n = static_cast<double>(p.size());
  std::vector<double> s(p.size());
  for (int k = 0; k < directions; ++k) {
    // Normals over [0, pi): a half-plane and its complement deviate equally.
    const double phi = kPi * k / directions;
    for (size_t i = 0; i < p.size(); ++i) s[i] = p[i].x * std::cos(phi) + p[i].y * std::sin(phi);
    std::sort(s.begin(), s.end());
    // Between consecutive projections the count is fixed and the area grows,
    // so the extremes sit at the projections: count without and with the point.
    for (size_t i = 0; i < s.size(); ++i) {
      const double area = half_plane_area(phi, s[i]);
      const size_t below = std::lower_bound(s.begin(), s.end(), s[i]) - s.begin();
      const size_t upto = std::upper_bound(s.begin(), s.end(), s[i]) - s.begin();
      const double dev = std::max(std::abs(area - below / n), std::abs(area - upto / n));
      if (dev > d.value) {
        d.value = dev;
        d.normal_deg = 180.0 * k / directions;
      }
    }
    if (progress) progress(k + 1, directions);
  }
  return d;
}

}  // namespace aapat
