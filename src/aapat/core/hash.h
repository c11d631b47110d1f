// FNV-1a, 64 bits: a fast hash of bytes for file names and checksums (the
// reference cache's names, a checkpoint's records), not for security.
#pragma once

#include <cstdint>
#include <string_view>

namespace aapat {

inline uint64_t fnv1a(std::string_view bytes) {
  uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

}  // namespace aapat
