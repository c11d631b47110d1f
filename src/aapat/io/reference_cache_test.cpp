#include "aapat/io/reference_cache.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace aapat {
namespace {

namespace fs = std::filesystem;

TEST(ReferenceCache, StoresReadsBackAndRecomputesADamagedFile) {
  const fs::path dir = fs::path(::testing::TempDir()) / "aapat_reference_cache_test";
  fs::remove_all(dir);
  std::vector<std::string> warnings;
  const ReferenceSource cached =
      cached_references(dir.string(), [&](const std::string& w) { warnings.push_back(w); });
  const Scene scene = make_scene("spiral", 24, 20);
  const ReferenceSettings r{16, "mitchell", 7};
  const Image direct = render_reference(scene, 24, 20, r, 0.5);
  const Image first = cached(scene, 24, 20, r, 0.5);
  EXPECT_EQ(first.values, direct.values);
  std::vector<fs::path> files(fs::directory_iterator(dir), fs::directory_iterator{});
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);  // read back
  EXPECT_TRUE(warnings.empty());
  // Values changed after they were written (a finite double, then a NaN):
  // the checksum says so, the reference is rendered afresh, a warning names the file.
  for (const char byte : {char{0x3f}, char{0x7f}}) {
    {
      std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
      f.seekp(-1, std::ios::end);
      f.put(byte);
      if (byte == 0x7f) {  // the last value all ones: a NaN
        f.seekp(-8, std::ios::end);
        for (int k = 0; k < 7; ++k) f.put(static_cast<char>(0xff));
      }
    }
    const size_t before = warnings.size();
    const Image again = cached(scene, 24, 20, r, 0.5);
    EXPECT_EQ(again.values, direct.values);
    EXPECT_EQ(again.offset, 0.5);
    ASSERT_EQ(warnings.size(), before + 1);
    EXPECT_NE(warnings.back().find(files[0].string()), std::string::npos) << warnings.back();
    EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);  // rewritten whole
    EXPECT_EQ(warnings.size(), before + 1);
  }
  // Other parameters: another file.
  cached(scene, 24, 20, ReferenceSettings{16, "mitchell", 8}, 0.5);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2);
  // A truncated file is recomputed and rewritten.
  fs::resize_file(files[0], 100);
  EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);
  EXPECT_EQ(cached(scene, 24, 20, r, 0.5).values, direct.values);
  fs::remove_all(dir);
}

// A killed writer's temporary in the cache folder is removed by the next
// run; a live process's (this one's, PID 1's) and a recent one stay.
TEST(ReferenceCache, ALaterRunRemovesAKilledWritersTemporaries) {
  const fs::path dir = fs::path(::testing::TempDir()) / "aapat_reference_cache_orphans";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(1);
  const long dead = 4194301;  // above any PID in use here (pid_max is 4194304 at most)
  ASSERT_NE(::kill(static_cast<pid_t>(dead), 0), 0);
  const fs::path orphan = dir / fmt::format("reference-1.bin.tmp.{}.0", dead);
  const fs::path recent = dir / fmt::format("reference-2.bin.tmp.{}.0", dead);
  const fs::path alive = dir / "reference-3.bin.tmp.1.0";
  const fs::path mine =
      dir / fmt::format("reference-4.bin.tmp.{}.0", static_cast<long>(::getpid()));
  for (const fs::path& p : {orphan, recent, alive, mine}) std::ofstream(p) << "partial";
  for (const fs::path& p : {orphan, alive, mine}) fs::last_write_time(p, old);
  cached_references(dir.string());
  EXPECT_FALSE(fs::exists(orphan));
  EXPECT_TRUE(fs::exists(recent));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(mine));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace aapat
