#include "aapat/io/atomic_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "aapat/core/geometry.h"
#include "testing/cli_run.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

namespace fs = std::filesystem;

size_t temporaries_in(const fs::path& dir) {
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().string().find(".tmp.") != std::string::npos;
  return n;
}

TEST(AtomicFile, ATransactionCommitsAllOrRollsBackAll) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  const std::string a = (dir / "a.txt").string(), b = (dir / "b.txt").string();
  fs::remove(b);  // from an earlier run
  std::ofstream(a) << "old";
  {
    OutputTransaction t;
    write_file_atomically(a, "new a");
    write_file_atomically(b, "new b");
    EXPECT_EQ(testing::slurp(a), "old");  // nothing appears before the commit
    EXPECT_FALSE(fs::exists(b));
  }  // no commit: rolled back
  EXPECT_EQ(testing::slurp(a), "old");
  EXPECT_FALSE(fs::exists(b));
  EXPECT_EQ(temporaries_in(dir), 0u);
  {
    OutputTransaction t;
    write_file_atomically(a, "first");
    // A second write of a path is two outputs naming one file: refused.
    EXPECT_THROW(write_file_atomically(a, "second"), Error);
    EXPECT_THROW(write_file_atomically((dir / "." / "a.txt").string(), "second"), Error);
    write_file_atomically(b, "new b");
    t.commit();
  }
  EXPECT_EQ(testing::slurp(a), "first");
  EXPECT_EQ(testing::slurp(b), "new b");
  EXPECT_EQ(temporaries_in(dir), 0u);
}

TEST(AtomicFile, FilesWrittenNowAreDeletedOnRollbackUnlessKept) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  const std::string frame = (dir / "frame.png").string(), cache = (dir / "cache.bin").string();
  fs::remove(frame);
  fs::remove(cache);
  {
    OutputTransaction t;
    write_file_now(frame, "f");
    write_file_now(cache, "c", /*keep_on_rollback=*/true);
    EXPECT_TRUE(fs::exists(frame));  // there for another program to read
  }
  EXPECT_FALSE(fs::exists(frame));
  EXPECT_EQ(testing::slurp(cache), "c");
}

TEST(AtomicFile, FoldersMadeByAFailedCommandAreRemoved) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path() / "made";
  fs::remove_all(dir);
  {
    OutputTransaction t;
    ensure_directory((dir / "deeper").string(), "--frames-dir");
    write_file_now((dir / "deeper" / "frame.png").string(), "f");
  }
  EXPECT_FALSE(fs::exists(dir));
  {
    OutputTransaction t;
    ensure_directory((dir / "deeper").string(), "--frames-dir");
    t.commit();
  }
  EXPECT_TRUE(fs::is_directory(dir / "deeper"));
}

TEST(AtomicFile, ASignalDuringAWriteRemovesTheTemporaries) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  const std::string target = (dir / "out.json").string();
  const pid_t pid = fork();
  if (pid == 0) {
    remove_temporaries_on_signals();
    OutputTransaction t;
    write_file_atomically(target, "staged, not yet renamed");
    std::raise(SIGTERM);
    _exit(0);  // not reached
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));  // the process still ends as the signal says
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(target));
  EXPECT_EQ(temporaries_in(dir), 0u);
}

// A signal at any moment of a commit: the set of outputs is all old or all
// new, never a mix. Each trial stages many files, then a second thread sends
// SIGTERM after a delay spread over the time before, during and after the
// renames; the process still ends by the signal.
TEST(AtomicFile, ASignalDuringACommitLeavesTheOldSetOrTheNewOne) {
  const fs::path dir = fs::path(testing::temp_path("commit-set")).parent_path() / "commit-set";
  fs::create_directories(dir);
  constexpr int kFiles = 200, kTrials = 24;
  std::vector<std::string> paths;
  for (int i = 0; i < kFiles; ++i) paths.push_back((dir / fmt::format("out-{}.txt", i)).string());
  int mixed = 0, old_sets = 0, new_sets = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    for (const std::string& p : paths) std::ofstream(p) << "old";
    const auto delay = std::chrono::microseconds(150 * trial);
    const pid_t pid = fork();
    if (pid == 0) {
      remove_temporaries_on_signals();
      OutputTransaction t;
      for (const std::string& p : paths) write_file_atomically(p, "new");
      std::thread killer([delay] {
        std::this_thread::sleep_for(delay);
        kill(getpid(), SIGTERM);
      });
      t.commit();
      killer.join();
      for (;;) pause();  // the signal ends the process
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    int fresh = 0;
    for (const std::string& p : paths) {
      std::ifstream in(p);
      std::string text;
      in >> text;
      fresh += text == "new";
    }
    mixed += fresh != 0 && fresh != kFiles;
    old_sets += fresh == 0;
    new_sets += fresh == kFiles;
    EXPECT_EQ(temporaries_in(dir), 0u) << "trial " << trial;
  }
  EXPECT_EQ(mixed, 0) << old_sets << " old sets, " << new_sets << " new sets";
  EXPECT_GT(old_sets + new_sets, 0);
  fs::remove_all(dir);
}

TEST(AtomicFile, ReadingNamesMissingFoldersAndOversizedFiles) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  EXPECT_EQ(testing::error_message([&] { read_file((dir / "none").string(), "scene file"); }),
            "cannot read scene file '" + (dir / "none").string() + "': no such file");
  EXPECT_EQ(testing::error_message([&] { read_file(dir.string(), "scene file"); }),
            "cannot read scene file '" + dir.string() + "': it is a folder, not a file");
  const std::string big = (dir / "big").string();
  std::ofstream(big) << "0123456789";
  EXPECT_EQ(testing::error_message([&] { read_file(big, "point file", 4); }),
            "cannot read point file '" + big + "': 10 bytes exceed the limit of 4 bytes");
  EXPECT_EQ(testing::error_message([&] { ensure_directory(big, "--best-dir"); }),
            "--best-dir '" + big + "': exists and is not a folder");
}

}  // namespace
}  // namespace aapat
