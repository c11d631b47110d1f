// The WebAssembly build's stand-in for oneTBB's parallel_sort.
#pragma once
#include <algorithm>

namespace tbb {
template <typename Iterator>
void parallel_sort(Iterator first, Iterator last) {
  std::sort(first, last);
}
}  // namespace tbb
