// Runs a test on every Highway code path this machine runs, each pinned in
// turn (the pin lifted at the end, whatever happens): the SIMD kernels must
// give the same bits on every path.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "aapat/core/metric_simd.h"

namespace aapat::testing {

class EveryPath {
 public:
  ~EveryPath() { pin_simd_target(0); }
  template <class F>
  void run(F&& test) {
    for (const int64_t target : simd_targets_here()) {
      pin_simd_target(target);
      SCOPED_TRACE(simd_target_name(target));
      test();
    }
  }
};

}  // namespace aapat::testing
