#include "aapat/core/half_plane_area.h"
#include "aapat/core/portable_math.h"

#include <algorithm>
#include <cmath>

namespace aapat {

HalfPlaneArea::HalfPlaneArea(double phi) {
  // {p : p . n <= t} for n = (c, s) cut with [0,1]^2, in closed form. With
  // c < 0, x -> 1 - x turns it into the case c >= 0 at t - c. Then the
  // corners project to 0 <= lo <= hi <= lo + hi (lo, hi the smaller and the
  // larger of |c|, s): a growing triangle, a band of constant width, and the
  // square less a shrinking triangle.
  const double c = portable_cos(phi), s = portable_sin(phi);
  a_ = std::abs(c);
  b_ = std::abs(s);
  negative_c_ = c < 0;
  negative_s_ = s < 0;
  c_ = c;
  s_ = s;
  lo_ = std::min(a_, b_);
  hi_ = std::max(a_, b_);
  total_ = a_ + b_;
}

double HalfPlaneArea::operator()(double t) const {
  if (negative_c_) t -= c_;
  if (negative_s_) t -= s_;
  if (t <= 0) return 0;
  if (t >= total_) return 1;
  if (lo_ < 1e-12) return std::min(1.0, t / hi_);  // an edge parallel to a side
  if (t <= lo_) return t * t / (2 * a_ * b_);
  if (t <= hi_) return (t - lo_ / 2) / hi_;
  return 1 - (total_ - t) * (total_ - t) / (2 * a_ * b_);
}

double half_plane_area(double phi, double t) {
  return HalfPlaneArea(phi)(t);
}

}  // namespace aapat
