// The WebAssembly build's stand-in for oneTBB's global_control: one thread
// always, so a limit on threads has nothing to limit.
#pragma once
#include <cstddef>

namespace tbb {
class global_control {
 public:
  enum parameter { max_allowed_parallelism };
  global_control(parameter, std::size_t) {}
  static std::size_t active_value(parameter) { return 1; }
};
}  // namespace tbb
