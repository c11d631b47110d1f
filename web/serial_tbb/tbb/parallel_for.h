// The WebAssembly build's stand-in for oneTBB's parallel_for: the same loop,
// in order, on the calling thread. The library's results do not depend on the
// order (same seed, same output, any thread count), so they are the native
// build's.
#pragma once
#include <type_traits>

#include "tbb/blocked_range.h"

namespace tbb {
template <typename Index, typename Body>
void parallel_for(Index first, Index last, const Body& body) {
  for (Index i = first; i < last; ++i) body(i);
}
template <typename Index, typename Body>
void parallel_for(const blocked_range<Index>& range, const Body& body) {
  body(range);
}
}  // namespace tbb
