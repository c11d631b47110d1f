#include "aapat/core/hash.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <string>

namespace aapat {
namespace {

// FNV-1a's published test vectors (64-bit): the empty string and "a".
TEST(Hash, Fnv1aMatchesItsPublishedVectors) {
  EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
}

// Damage the cache check must see: any one bit flipped, in the lanes or the
// tail, and any change of length (a value cut off, a byte appended).
RC_GTEST_PROP(Hash, Checksum64SeesEveryFlippedBitAndLength, ()) {
  const auto bytes = *rc::gen::container<std::string>(rc::gen::arbitrary<char>());
  RC_PRE(!bytes.empty());
  const size_t at = *rc::gen::inRange<size_t>(0, bytes.size());
  const int bit = *rc::gen::inRange(0, 8);
  std::string damaged = bytes;
  damaged[at] = static_cast<char>(damaged[at] ^ (1 << bit));
  RC_ASSERT(checksum64(damaged) != checksum64(bytes));
  RC_ASSERT(checksum64(bytes + '\0') != checksum64(bytes));
  RC_ASSERT(checksum64(bytes.substr(0, bytes.size() - 1)) != checksum64(bytes));
}

TEST(Hash, Checksum64SeesSwappedWords) {
  std::string a(64, '\0'), b(64, '\0');
  a[0] = b[8] = 1;  // the same words in another order
  EXPECT_NE(checksum64(a), checksum64(b));
}

}  // namespace
}  // namespace aapat
