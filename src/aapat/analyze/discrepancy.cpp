#include "aapat/analyze/discrepancy.h"

#include <fmt/format.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>

#include <atomic>
#include <mutex>
#include <numeric>

#include "aapat/analyze/double_double.h"
#include "aapat/analyze/radix_sort.h"

namespace aapat {

namespace {

// A Fenwick tree over y ranks: how many points were added below a rank, and
// the sum of their 1 - y.
class RankSums {
 public:
  explicit RankSums(size_t n) : count_(n + 1, 0), sum_(n + 1) {}
  void add(size_t rank, DoubleDouble one_minus_y) {
    for (size_t i = rank + 1; i < count_.size(); i += i & (~i + 1)) {
      ++count_[i];
      sum_[i] += one_minus_y;
    }
  }
  // The points added at ranks < rank, and their sum of 1 - y.
  std::pair<size_t, DoubleDouble> below(size_t rank) const {
    size_t c = 0;
    DoubleDouble s;
    for (size_t i = rank; i > 0; i -= i & (~i + 1)) {
      c += count_[i];
      s += sum_[i];
    }
    return {c, s};
  }

 private:
  std::vector<size_t> count_;
  std::vector<DoubleDouble> sum_;
};

DoubleDouble one_minus(DoubleDouble v) {
  return DoubleDouble(1.0) - v;
}

}  // namespace

double l2_star_discrepancy(const std::vector<Vec2>& p) {
  // Warnock 1972: T^2 = 1/9 - (2/N) sum_i prod_k (1 - x_ik^2)/2
  //                     + (1/N^2) sum_i sum_j prod_k (1 - max(x_ik, x_jk)).
  // The pair sum in O(N log N), in the spirit of Heinrich's algorithm: in
  // order of x, point j meets each earlier point i (x_i <= x_j) with
  // (1 - x_j)(1 - max(y_i, y_j)), and over those i the second factor sums to
  // (how many have y_i <= y_j) (1 - y_j) + (the sum of 1 - y_i over the
  // others): two queries of a Fenwick tree over y ranks. (Ties in y go
  // either way: 1 - y_i = 1 - y_j.) Everything is double-double: the three
  // terms are near 1/9 and cancel to T^2, which is 1e-8 at 65,536 points.
  check_l2_star_size(p.size());
  const size_t n = p.size();
  if (n == 0) return std::sqrt(1.0 / 9);
  std::vector<size_t> by_x(n), by_y(n), rank(n);
  std::iota(by_x.begin(), by_x.end(), 0);
  std::iota(by_y.begin(), by_y.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](size_t a, size_t b) { return p[a].x < p[b].x; });
  std::sort(by_y.begin(), by_y.end(), [&](size_t a, size_t b) { return p[a].y < p[b].y; });
  for (size_t r = 0; r < n; ++r) rank[by_y[r]] = r;
  DoubleDouble single, diagonal, off_diagonal, added;  // added: the sum of 1 - y so far
  RankSums sums(n);
  for (size_t k = 0; k < n; ++k) {
    const Vec2 v = p[by_x[k]];
    const DoubleDouble ox = one_minus(v.x), oy = one_minus(v.y);
    single += one_minus(two_prod(v.x, v.x)) * one_minus(two_prod(v.y, v.y));
    diagonal += ox * oy;
    const auto [lower, lower_sum] = sums.below(rank[by_x[k]]);
    off_diagonal += ox * (DoubleDouble(static_cast<double>(lower)) * oy + (added - lower_sum));
    sums.add(rank[by_x[k]], oy);
    added += oy;
  }
  const double nn = static_cast<double>(n);
  const DoubleDouble ninth(1.0 / 9, std::fma(-9.0, 1.0 / 9, 1.0) / 9);
  const DoubleDouble t2 = ninth - single / (2 * nn) + (diagonal + off_diagonal * 2.0) / nn / nn;
  return std::sqrt(std::max(0.0, t2.value()));
}

void check_l2_star_size(size_t points) {
  if (points > kMaxL2StarPoints)
    throw Error(fmt::format("L2-star discrepancy: {} points exceed the limit of {}", points,
                            kMaxL2StarPoints));
}

namespace {

// Largest deviation over anchored boxes whose corners take the given x and
// y values (both sorted), counting points strictly inside (x < a, y < b) and
// on or inside. For each a the points left of it are kept sorted by y, and
// the b run upward with two pointers: O(N^2) in all.
double boxes_deviation(const std::vector<Vec2>& p, const std::vector<double>& xs,
                       const std::vector<double>& ys) {
  std::vector<size_t> by_x(p.size());
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](size_t a, size_t b) { return p[a].x < p[b].x; });
  const double n = static_cast<double>(p.size());
  std::vector<double> open_y, closed_y;  // y of the points left of a, kept sorted
  size_t next_open = 0, next_closed = 0;
  double worst = 0;
  auto insert = [](std::vector<double>& v, double y) {
    v.insert(std::upper_bound(v.begin(), v.end(), y), y);
  };
  for (double a : xs) {
    while (next_open < by_x.size() && p[by_x[next_open]].x < a)
      insert(open_y, p[by_x[next_open++]].y);
    while (next_closed < by_x.size() && p[by_x[next_closed]].x <= a)
      insert(closed_y, p[by_x[next_closed++]].y);
    size_t inside = 0, with_border = 0;
    for (double b : ys) {
      while (inside < open_y.size() && open_y[inside] < b) ++inside;
      while (with_border < closed_y.size() && closed_y[with_border] <= b) ++with_border;
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
  // worse of the two mixed comparisons (upper), and the grid boxes give a
  // lower bound. The counts of the boxes [0, g_i) x [0, g_j) are built one
  // grid column at a time, so memory is O(grid), not O(grid^2).
  const size_t g = static_cast<size_t>(grid);
  auto line = [&](size_t i) { return static_cast<double>(i) / grid; };
  // Point k lies left of line i (x < g_i) from i = its column on.
  std::vector<std::vector<size_t>> by_column(g + 1);
  std::vector<size_t> cy(p.size());
  for (size_t k = 0; k < p.size(); ++k) {
    const size_t cx = std::min(g, static_cast<size_t>(std::floor(p[k].x * grid)) + 1);
    cy[k] = std::min(g, static_cast<size_t>(std::floor(p[k].y * grid)) + 1);
    by_column[cx].push_back(k);
  }
  const double n = static_cast<double>(p.size());
  std::vector<size_t> column(g + 1, 0);                // points left of the line, by y cell
  std::vector<size_t> prev(g + 1, 0), next(g + 1, 0);  // and below each y line
  for (size_t i = 0; i < g; ++i) {
    for (size_t k : by_column[i + 1]) ++column[cy[k]];
    size_t running = 0;
    for (size_t j = 0; j <= g; ++j) {
      running += column[j];
      next[j] = running;  // points with x < g_{i+1}, y < g_j
    }
    for (size_t j = 0; j < g; ++j) {
      const double lo = prev[j] / n, hi = next[j + 1] / n;
      d.upper = std::max({d.upper, hi - line(i) * line(j), line(i + 1) * line(j + 1) - lo});
      d.lower = std::max(d.lower, std::abs(line(i + 1) * line(j + 1) - hi));
    }
    std::swap(prev, next);
  }
  return d;
}

double half_plane_area(double phi, double t) {
  // {p : p . n <= t} for n = (c, s) cut with [0,1]^2, in closed form. With
  // c < 0, x -> 1 - x turns it into the case c >= 0 at t - c. Then the
  // corners project to 0 <= lo <= hi <= lo + hi (lo, hi the smaller and the
  // larger of |c|, s): a growing triangle, a band of constant width, and the
  // square less a shrinking triangle.
  const double c = std::cos(phi), s = std::sin(phi);
  const double a = std::abs(c), b = std::abs(s);
  if (c < 0) t -= c;
  if (s < 0) t -= s;
  const double lo = std::min(a, b), hi = std::max(a, b), total = a + b;
  if (t <= 0) return 0;
  if (t >= total) return 1;
  if (lo < 1e-12) return std::min(1.0, t / hi);  // an edge parallel to a side
  if (t <= lo) return t * t / (2 * a * b);
  if (t <= hi) return (t - lo / 2) / hi;
  return 1 - (total - t) * (total - t) / (2 * a * b);
}

void check_discrepancy_size(size_t points) {
  if (points > kMaxDiscrepancyPoints)
    throw Error(fmt::format(
        "discrepancy: {} points exceed the limit of {} for the star and edge discrepancies (the "
        "L2-star discrepancy alone takes up to {})",
        points, kMaxDiscrepancyPoints, kMaxL2StarPoints));
}

EdgeDiscrepancy edge_discrepancy(const std::vector<Vec2>& p, int directions,
                                 const std::function<void(int, int)>& progress) {
  check_discrepancy_size(p.size());
  if (directions < 1) throw Error(fmt::format("edge discrepancy: {} directions", directions));
  const double n = static_cast<double>(p.size());
  // Each direction alone, in parallel; then the worst in direction order
  // (ties: the first), so any thread count gives the same answer.
  std::vector<double> worst(static_cast<size_t>(directions), 0.0);
  std::atomic<int> done{0};
  std::mutex report;
  tbb::parallel_for(tbb::blocked_range<int>(0, directions), [&](const auto& range) {
    std::vector<double> s(p.size());
    std::vector<uint64_t> scratch;
    for (int k = range.begin(); k != range.end(); ++k) {
      // Normals over [0, pi): a half-plane and its complement deviate equally.
      const double phi = kPi * k / directions, c = std::cos(phi), sn = std::sin(phi);
      for (size_t i = 0; i < p.size(); ++i) s[i] = p[i].x * c + p[i].y * sn;
      radix_sort(s, scratch);
      // Between consecutive projections the count is fixed and the area
      // grows, so the extremes sit at the projections: a sweep over groups
      // of equal ones, counting the points below the group and up to its end.
      double dev = 0;
      for (size_t i = 0; i < s.size();) {
        size_t end = i + 1;
        while (end < s.size() && s[end] == s[i]) ++end;
        const double area = half_plane_area(phi, s[i]);
        dev = std::max({dev, std::abs(area - i / n), std::abs(area - end / n)});
        i = end;
      }
      worst[static_cast<size_t>(k)] = dev;
      const int finished = ++done;
      if (progress) {
        std::lock_guard<std::mutex> lock(report);
        progress(finished, directions);
      }
    }
  });
  EdgeDiscrepancy d;
  for (int k = 0; k < directions; ++k)
    if (worst[static_cast<size_t>(k)] > d.value) {
      d.value = worst[static_cast<size_t>(k)];
      d.normal_deg = 180.0 * k / directions;
    }
  return d;
}

}  // namespace aapat
