#include "aapat/analyze/radix_sort.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace aapat {
namespace {

// memcpy, not std::bit_cast: the WebAssembly build's libc++ (emscripten 3.1.6)
// has no bit_cast.
uint64_t key_of(double v) {
  uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b & (uint64_t{1} << 63) ? ~b : b | (uint64_t{1} << 63);
}

double value_of(uint64_t k) {
  const uint64_t b = k & (uint64_t{1} << 63) ? k & ~(uint64_t{1} << 63) : ~k;
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
}

}  // namespace

void radix_sort(std::vector<double>& values, std::vector<uint64_t>& scratch) {
  const size_t n = values.size();
  // Below a few thousand values the six passes over 2048 counters cost more
  // than comparing.
  if (n < 4096) {
    std::sort(values.begin(), values.end());
    return;
  }
  scratch.resize(2 * n);
  uint64_t* from = scratch.data();
  uint64_t* to = scratch.data() + n;
  for (size_t i = 0; i < n; ++i) from[i] = key_of(values[i]);
  std::array<size_t, 2048> count;
  for (int shift = 0; shift < 64; shift += 11) {
    count.fill(0);
    for (size_t i = 0; i < n; ++i) ++count[(from[i] >> shift) & 0x7ff];
    size_t sum = 0;
    for (size_t& c : count) {
      const size_t here = c;
      c = sum;
      sum += here;
    }
    for (size_t i = 0; i < n; ++i) to[count[(from[i] >> shift) & 0x7ff]++] = from[i];
    std::swap(from, to);
  }
  for (size_t i = 0; i < n; ++i) values[i] = value_of(from[i]);
}

}  // namespace aapat
