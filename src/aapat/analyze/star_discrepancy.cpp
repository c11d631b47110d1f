#include "aapat/analyze/star_discrepancy.h"

#include "aapat/core/interrupt.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <tbb/parallel_for.h>

namespace aapat {
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

// The points sorted by x and by y, for the exact sweeps along one axis.
struct SortedPoints {
  std::vector<Vec2> by_x, by_y;
  double n = 0;
  explicit SortedPoints(const std::vector<Vec2>& p) : by_x(p), by_y(p), n(double(p.size())) {
    std::sort(by_x.begin(), by_x.end(), [](Vec2 a, Vec2 b) { return a.x < b.x; });
    std::sort(by_y.begin(), by_y.end(), [](Vec2 a, Vec2 b) { return a.y < b.y; });
  }
};

// Which way a box deviates: more points than its area (the closed box
// [0, a] x [0, b]) or fewer (the open one).
enum class Deviation { excess, deficit };

struct Corner {
  double a = 1, b = 1, value = 0;  // value: the box's exact deviation that way
};

// With one corner coordinate fixed, the exact best other one, in one sweep of
// the points sorted by the free coordinate. The excess is largest at a
// point's coordinate (the count just rose), the deficit just before one, at
// the coordinate itself with the box open, or at 1.
Corner best_along(const std::vector<Vec2>& sorted, bool free_is_y, double fixed, Deviation way,
                  double n) {
  auto free = [&](Vec2 v) { return free_is_y ? v.y : v.x; };
  auto other = [&](Vec2 v) { return free_is_y ? v.x : v.y; };
  Corner best{1, 1, -1};
  double count = 0;
  for (size_t i = 0; i < sorted.size();) {
    const double t = free(sorted[i]);
    if (way == Deviation::deficit && t * fixed - count / n > best.value)
      best = {t, fixed, t * fixed - count / n};
    size_t end = i;
    for (; end < sorted.size() && free(sorted[end]) == t; ++end)
      count += way == Deviation::excess ? other(sorted[end]) <= fixed : other(sorted[end]) < fixed;
    if (way == Deviation::excess && count / n - t * fixed > best.value)
      best = {t, fixed, count / n - t * fixed};
    i = end;
  }
  if (way == Deviation::deficit && fixed - count / n > best.value)
    best = {1, fixed, fixed - count / n};
  if (free_is_y) std::swap(best.a, best.b);
  return best;
}

// Moves one coordinate at a time to its best position until neither move
// improves: a box whose deviation is a local maximum, and a lower bound.
Corner climb(const SortedPoints& s, Corner c, Deviation way) {
  c.value = -1;
  for (int round = 0; round < 64; ++round) {
    const Corner along_y = best_along(s.by_y, true, c.a, way, s.n);
    const Corner along_x = best_along(s.by_x, false, along_y.b, way, s.n);
    if (!(along_x.value > c.value)) break;
    c = along_x;
  }
  return c;
}

// The k largest values seen, with where they were.
template <size_t K>
class Largest {
 public:
  void offer(double value, double a, double b) {
    if (!(value > best_.back().value)) return;
    size_t i = K - 1;
    for (; i > 0 && best_[i - 1].value < value; --i) best_[i] = best_[i - 1];
    best_[i] = {a, b, value};
  }
  const std::array<Corner, K>& corners() const { return best_; }

 private:
  std::array<Corner, K> best_{};
};

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
  // The lattice's worst boxes each way: the starts of the climbs. The
  // columns run in chunks in parallel, each starting from the counts of the
  // points left of its first line; the chunks' results are merged in column
  // order, so the starts are those of one pass in order, on any thread count.
  constexpr size_t kStarts = 16;
  struct Chunk {
    double upper = 0;
    Largest<kStarts> excess, deficit;
  };
  const size_t chunks = std::min<size_t>(g, 64);
  std::vector<Chunk> results(chunks);
  tbb::parallel_for(size_t{0}, chunks, [&](size_t chunk) {
    throw_if_interrupted();
    const size_t first = chunk * g / chunks, last = (chunk + 1) * g / chunks;
    Chunk& r = results[chunk];
    std::vector<size_t> column(g + 1, 0);  // points left of the line, by y cell
    for (size_t i = 1; i <= first; ++i)
      for (size_t k : by_column[i]) ++column[cy[k]];
    std::vector<size_t> prev(g + 1, 0), next(g + 1, 0);  // and below each y line
    size_t running = 0;
    for (size_t j = 0; j <= g; ++j) {
      running += column[j];
      prev[j] = running;  // points with x < g_first, y < g_j
    }
    for (size_t i = first; i < last; ++i) {
      for (size_t k : by_column[i + 1]) ++column[cy[k]];
      running = 0;
      for (size_t j = 0; j <= g; ++j) {
        running += column[j];
        next[j] = running;  // points with x < g_{i+1}, y < g_j
      }
      for (size_t j = 0; j < g; ++j) {
        const double lo = prev[j] / n, hi = next[j + 1] / n;
        r.upper = std::max({r.upper, hi - line(i) * line(j), line(i + 1) * line(j + 1) - lo});
        const double area = line(i + 1) * line(j + 1);
        r.excess.offer(hi - area, line(i + 1), line(j + 1));
        r.deficit.offer(area - hi, line(i + 1), line(j + 1));
      }
      std::swap(prev, next);
    }
  });
  Largest<kStarts> excess, deficit;
  for (const Chunk& r : results) {
    d.upper = std::max(d.upper, r.upper);
    for (const Corner& c : r.excess.corners()) excess.offer(c.value, c.a, c.b);
    for (const Corner& c : r.deficit.corners()) deficit.offer(c.value, c.a, c.b);
  }
  const SortedPoints sorted(p);
  for (const Corner& c : excess.corners())
    if (c.value > 0) d.lower = std::max(d.lower, climb(sorted, c, Deviation::excess).value);
  for (const Corner& c : deficit.corners())
    if (c.value > 0) d.lower = std::max(d.lower, climb(sorted, c, Deviation::deficit).value);
  return d;
}

}  // namespace aapat
