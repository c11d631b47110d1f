#pragma once

#include <cmath>
#include <cstdint>
#include <iterator>
#include <random>
#include <utility>

#include "aapat/core/portable_math.h"
#include "aapat/generate/unit_random.h"

namespace aapat {

// The draws aapat makes from a std::mt19937_64, written out so that a seed
// gives the same numbers with every standard library. The engine itself is
// specified to the bit by the standard; its distributions and std::shuffle
// are not (libc++, which the WebAssembly build uses, draws n-rooks'
// permutations differently from libstdc++). Each reproduces libstdc++'s
// algorithm, so the native outputs stayed what they were.

// A uniform double in [a, b): a + (b - a) u as libstdc++ computes it.
inline double uniform_real(std::mt19937_64& rng, double a, double b) {
  return unit_double(rng) * (b - a) + a;
}

// A uniform integer in [0, n), n >= 1: Lemire's nearly divisionless method on
// the full 64-bit product (Lemire 2019, "Fast random integer generation in an
// interval"), as libstdc++ draws it from a 64-bit engine.
inline uint64_t uniform_below(std::mt19937_64& rng, uint64_t n) {
  // The 128-bit product of two 64-bit numbers from 32-bit halves, so that it
  // needs no compiler's 128-bit integer.
  const auto product = [n](uint64_t x, uint64_t& low) {
    const uint64_t x0 = x & 0xffffffffu, x1 = x >> 32, n0 = n & 0xffffffffu, n1 = n >> 32;
    const uint64_t p00 = x0 * n0, p01 = x0 * n1, p10 = x1 * n0, p11 = x1 * n1;
    const uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    low = (middle << 32) | (p00 & 0xffffffffu);
    return p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  };
  uint64_t low = 0;
  uint64_t high = product(rng(), low);
  if (low < n) {
    const uint64_t threshold = (0 - n) % n;
    while (low < threshold) high = product(rng(), low);
  }
  return high;
}

// A uniform integer in [lo, hi], lo <= hi.
inline int64_t uniform_int(std::mt19937_64& rng, int64_t lo, int64_t hi) {
  const uint64_t range = static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo);
  if (range == UINT64_MAX) return static_cast<int64_t>(rng());
  return static_cast<int64_t>(static_cast<uint64_t>(lo) + uniform_below(rng, range + 1));
}

// true with probability p.
inline bool bernoulli(std::mt19937_64& rng, double p) {
  return unit_double(rng) < p;
}

// A Fisher-Yates shuffle drawn as libstdc++'s std::shuffle draws it: while
// n^2 fits in the engine's range, two swap positions from one draw.
template <typename RandomIt>
void shuffle(RandomIt first, RandomIt last, std::mt19937_64& rng) {
  if (first == last) return;
  const uint64_t n = static_cast<uint64_t>(last - first);
  if (UINT64_MAX / n >= n) {
    RandomIt i = first + 1;
    if (n % 2 == 0) std::iter_swap(i++, first + static_cast<std::ptrdiff_t>(uniform_below(rng, 2)));
    while (i != last) {
      const uint64_t b0 = static_cast<uint64_t>(i - first) + 1, b1 = b0 + 1;
      const uint64_t x = uniform_below(rng, b0 * b1);
      std::iter_swap(i++, first + static_cast<std::ptrdiff_t>(x / b1));
      std::iter_swap(i++, first + static_cast<std::ptrdiff_t>(x % b1));
    }
    return;
  }
  for (RandomIt i = first + 1; i != last; ++i)
    std::iter_swap(i, first + static_cast<std::ptrdiff_t>(
                                  uniform_below(rng, static_cast<uint64_t>(i - first) + 1)));
}

// Standard normal draws by Marsaglia's polar method, the second of each pair
// kept for the next call, as libstdc++'s std::normal_distribution draws them
// (its logarithm aapat's own, the same bits everywhere: core/portable_math.h).
class Gaussian {
 public:
  Gaussian(double mean = 0, double sd = 1) : mean_(mean), sd_(sd) {}
  double operator()(std::mt19937_64& rng) {
    double v = 0;
    if (saved_) {
      saved_ = false;
      v = kept_;
    } else {
      double x = 0, y = 0, r2 = 0;
      do {
        x = 2.0 * unit_double(rng) - 1.0;
        y = 2.0 * unit_double(rng) - 1.0;
        r2 = x * x + y * y;
      } while (r2 > 1.0 || r2 == 0.0);
      const double mult = std::sqrt(-2 * portable_log_fast(r2) / r2);
      kept_ = x * mult;
      saved_ = true;
      v = y * mult;
    }
    return v * sd_ + mean_;
  }

 private:
  double mean_, sd_;
  double kept_ = 0;
  bool saved_ = false;
};

}  // namespace aapat
