#include "aapat/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
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

bool is_kind(const std::string& path, mode_t kind) {
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && (st.st_mode & S_IFMT) == kind;
}

// A FIFO is written in place: its reader gets the content, and it stays a
// FIFO (the rename would have replaced it with a file, and the reader would
// have got nothing).
TEST(OutputTarget, AFifoIsWrittenInPlaceAndStaysAFifo) {
  const std::string fifo = testing::temp_path("out.fifo");
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Without a reader the write is refused at once, not waited on.
  EXPECT_NE(
      testing::error_message([&] { write_file_atomically(fifo, "x"); }).find("no process reads it"),
      std::string::npos);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  {
    OutputTransaction t;
    write_file_atomically(fifo, "through the pipe");
    t.commit();
  }
  char buffer[64] = {};
  const ssize_t n = ::read(reader, buffer, sizeof(buffer));
  ::close(reader);
  EXPECT_EQ(std::string(buffer, n > 0 ? static_cast<size_t>(n) : 0), "through the pipe");
  EXPECT_TRUE(is_kind(fifo, S_IFIFO));
  fs::remove(fifo);
}

// A character device is written in place, never replaced: /dev/null stays
// the device (a test run as root once replaced it with a file).
TEST(OutputTarget, ACharacterDeviceStaysADevice) {
  ASSERT_TRUE(is_kind("/dev/null", S_IFCHR));
  write_file_atomically("/dev/null", "nothing");
  write_file_now("/dev/null", "nothing");
  check_file_target("/dev/null", "--output");
  EXPECT_TRUE(is_kind("/dev/null", S_IFCHR));
  if (is_kind("/dev/full", S_IFCHR)) {  // a device that refuses: the error names it
    EXPECT_NE(testing::error_message([] {
                write_file_atomically("/dev/full", "x");
              }).find("cannot write '/dev/full'"),
              std::string::npos);
    EXPECT_TRUE(is_kind("/dev/full", S_IFCHR));
  }
}

// A symbolic link is followed, through a chain of links: the file it names
// gets the content, and the links stay links.
TEST(OutputTarget, ASymlinkIsFollowedAndStays) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  const fs::path target = dir / "target.txt", link = dir / "link.txt", link2 = dir / "link2.txt";
  for (const fs::path& f : {target, link, link2}) fs::remove(f);
  std::ofstream(target) << "old";
  fs::create_symlink("target.txt", link);
  fs::create_symlink(link, link2);
  write_file_atomically(link2.string(), "new");
  EXPECT_TRUE(is_kind(link.string(), S_IFLNK));
  EXPECT_TRUE(is_kind(link2.string(), S_IFLNK));
  std::ifstream in(target);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "new");
  // A dangling link: the file it names is created.
  fs::remove(target);
  write_file_atomically(link.string(), "made");
  EXPECT_TRUE(fs::is_regular_file(target));
  EXPECT_TRUE(is_kind(link.string(), S_IFLNK));
}

// A socket (and a block device, and anything else but a file, a device or
// a FIFO) is refused before anything is written, and left as it was.
TEST(OutputTarget, ASocketIsRefusedAndLeftAsItWas) {
  const std::string path = testing::temp_path("out.sock");
  fs::remove(path);
  const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof(addr.sun_path));
  std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", path.c_str());
  ASSERT_EQ(::bind(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)), 0);
  EXPECT_NE(testing::error_message([&] { write_file_atomically(path, "x"); }).find("a socket"),
            std::string::npos);
  EXPECT_THROW(check_file_target(path, "--output"), Error);
  EXPECT_TRUE(is_kind(path, S_IFSOCK));
  ::close(fd);
  fs::remove(path);
}

// Two spellings of one file that does not exist yet are one output.
TEST(OutputTarget, TwoSpellingsOfANewFileAreOneOutput) {
  const fs::path dir = fs::path(testing::temp_path("x")).parent_path();
  const fs::path old = fs::current_path();
  fs::current_path(dir);
  fs::remove("same.txt");
  {
    OutputTransaction t;
    write_file_atomically("same.txt", "a");
    EXPECT_NE(testing::error_message([] {
                write_file_atomically("./same.txt", "b");
              }).find("two outputs"),
              std::string::npos);
    EXPECT_NE(testing::error_message([&] {
                write_file_atomically((dir / "same.txt").string(), "c");
              }).find("two outputs"),
              std::string::npos);
  }
  fs::current_path(old);
  EXPECT_FALSE(fs::exists(dir / "same.txt"));  // rolled back
}

}  // namespace
}  // namespace aapat
