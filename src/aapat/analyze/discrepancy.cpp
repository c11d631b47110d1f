#include "aapat/analyze/discrepancy.h"

#include <fmt/format.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <algorithm>
#include <cmath>

#include <atomic>
#include <mutex>
#include <numeric>

#include "aapat/analyze/l2_discrepancy.h"
#include "aapat/analyze/radix_sort.h"
#include "aapat/core/interrupt.h"
#include "aapat/core/portable_math.h"

namespace aapat {

double l2_star_discrepancy(const std::vector<Vec2>& points) {
  return l2_discrepancy(points, L2Kind::star);
}

void check_l2_star_size(size_t points) {
  if (points > kMaxL2StarPoints)
    throw Error(
        fmt::format("L2 discrepancy: {} points exceed the limit of {}", points, kMaxL2StarPoints));
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
    throw_if_interrupted();
    std::vector<double> s(p.size());
    std::vector<uint64_t> scratch;
    for (int k = range.begin(); k != range.end(); ++k) {
      // Normals over [0, pi): a half-plane and its complement deviate equally.
      const double phi = kPi * k / directions, c = portable_cos(phi), sn = portable_sin(phi);
      for (size_t i = 0; i < p.size(); ++i) s[i] = p[i].x * c + p[i].y * sn;
      const HalfPlaneArea area_below(phi);
      radix_sort(s, scratch);
      // Between consecutive projections the count is fixed and the area
      // grows, so the extremes sit at the projections: a sweep over groups
      // of equal ones, counting the points below the group and up to its end.
      double dev = 0;
      for (size_t i = 0; i < s.size();) {
        size_t end = i + 1;
        while (end < s.size() && s[end] == s[i]) ++end;
        const double area = area_below(s[i]);
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
