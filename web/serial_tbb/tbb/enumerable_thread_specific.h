// The WebAssembly build's stand-in for oneTBB's enumerable_thread_specific:
// one thread, so one value, made on first use.
#pragma once

namespace tbb {
template <class T>
class enumerable_thread_specific {
 public:
  T& local() { return value_; }

 private:
  T value_{};
};
}  // namespace tbb
