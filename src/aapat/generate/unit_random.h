#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace aapat {

// A uniform double in [0, 1) from a 64-bit Mersenne Twister: the value that
// libstdc++'s std::uniform_real_distribution<double>(0, 1) draws, bit for bit
// (one draw x, x / 2^64 rounded once, below 1), without the branch on x's top
// bit that converting an unsigned 64-bit integer takes: that bit is random,
// so the branch mispredicts half the time, and a reference draws two per sample.
inline double unit_double_of(uint64_t x) {
  // x = hi 2^32 + lo with both halves exact in a double (and converted as
  // signed integers, one instruction): one rounding of their sum is x rounded
  // to the nearest double, as the conversion rounds it.
  const double hi = static_cast<double>(static_cast<int64_t>(x >> 32)) * 0x1p32;
  const double lo = static_cast<double>(static_cast<int64_t>(x & 0xffffffffu));
  const double v = (hi + lo) * 0x1p-64;
  return v < 1 ? v : std::nextafter(1.0, 0.0);
}
inline double unit_double(std::mt19937_64& rng) {
  return unit_double_of(rng());
}

}  // namespace aapat
