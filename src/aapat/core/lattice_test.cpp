#include "aapat/core/lattice.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <cmath>

namespace aapat {
namespace {

RC_GTEST_PROP(Lattice, SnapIsNearestSymmetricAndKeepsTheRole, ()) {
  const double v = *rc::gen::inRange(-499999, 500000) / 1e6;  // inside (-1/2, 1/2)
  const double s = snap_coordinate(v, 16);
  RC_ASSERT(s * 16 == std::round(s * 16));   // on the lattice
  RC_ASSERT(std::abs(s) <= 7.0 / 16);        // still inside its pixel
  RC_ASSERT(snap_coordinate(-v, 16) == -s);  // mirrors stay mirrors
  if (std::abs(v) <= 7.0 / 16) RC_ASSERT(std::abs(s - v) <= 1.0 / 32 + 1e-15);  // nearest
}

}  // namespace
}  // namespace aapat
