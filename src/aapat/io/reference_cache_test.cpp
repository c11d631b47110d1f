#include "aapat/io/reference_cache.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace aapat {
namespace {

namespace fs = std::filesystem;

TEST(ReferenceCache, StoresReadsBackAndRecomputesADamagedFile) {
  const fs::path dir = fs::path(::testing::TempDir()) / "aapat_reference_cache_test";
  fs::remove_all(dir);
  const ReferenceSource cached = cached_references(dir.string());
  const Scene scene = make_scene("spiral", 24, 20);
  const ReferenceSettings r{16, "mitchell", 7};
  const Image direct = render_reference(scene, 24, 20, r, 0.5);
  const Image first = cached(scene, 24, 20, r, 0.5);
  EXPECT_EQ(first.values, direct.values);
  std::vector<fs::path> files(fs::directory_iterator(dir), fs::directory_iterator{});
  ASSERT_EQ(files.size(), 1u);
  // Read back: overwrite the stored values' last byte and see it come back.
  {
    std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(-1, std::ios::end);
    f.put(static_cast<char>(0x3f));  // still a finite double, a different value
  }
  const Image second = cached(scene, 24, 20, r, 0.5);
  EXPECT_NE(second.values, direct.values);
  EXPECT_EQ(second.offset, 0.5);
  // Other parameters: another file.
  cached(scene, 24, 20, ReferenceSettings{16, "mitchell", 8}, 0.5);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
  // A truncated file is a miss: recomputed and rewritten.
  fs::resize_file(files[0], 100);
  EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);
  EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace aapat
