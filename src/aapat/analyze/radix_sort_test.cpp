// The radix sort orders finite doubles as std::sort does: negatives, zeros
// of both signs, duplicates, subnormals and the extremes.
#include "aapat/analyze/radix_sort.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <limits>

namespace aapat {
namespace {

RC_GTEST_PROP(RadixSort, SortsLikeStdSort, ()) {
  const double specials[] = {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             std::numeric_limits<double>::denorm_min(),
                             -std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             0.5};
  const int n = *rc::gen::inRange(0, 12000);  // both sides of the std::sort cut-off
  std::vector<double> v;
  for (int i = 0; i < n; ++i)
    v.push_back(*rc::gen::arbitrary<bool>()
                    ? specials[*rc::gen::inRange<size_t>(0, std::size(specials))]
                    : *rc::gen::inRange(-1000000, 1000001) / 7919.0);
  std::vector<double> expected = v;
  std::sort(expected.begin(), expected.end());
  std::vector<uint64_t> scratch;
  radix_sort(v, scratch);
  RC_ASSERT(v == expected);  // == treats -0.0 and 0.0 as equal, as std::sort does
  RC_ASSERT(std::is_sorted(v.begin(), v.end()));
}

}  // namespace
}  // namespace aapat
