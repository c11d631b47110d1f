// The WebAssembly build's stand-in for oneTBB's blocked_range: the page runs
// the library on one thread (a web worker), so a range is just its bounds.
#pragma once
#include <cstddef>

namespace tbb {
template <typename T>
class blocked_range {
 public:
  blocked_range(T begin, T end, std::size_t = 1) : begin_(begin), end_(end) {}
  T begin() const { return begin_; }
  T end() const { return end_; }
  bool empty() const { return !(begin_ < end_); }

 private:
  T begin_, end_;
};
}  // namespace tbb
