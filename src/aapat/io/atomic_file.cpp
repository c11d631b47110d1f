#include "aapat/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// Temporary files in flight, for the signal handler: fixed slots it can read
// without locking. Past the slots a temporary is still removed on error, only
// not on a signal.
constexpr size_t kSignalSlots = 1024;
std::array<std::atomic<char*>, kSignalSlots> g_in_flight{};

void track_temporary(const std::string& tmp) {
  char* copy = strdup(tmp.c_str());
  for (auto& slot : g_in_flight) {
    char* expected = nullptr;
    if (slot.compare_exchange_strong(expected, copy)) return;
  }
  std::free(copy);
}

void untrack_temporary(const std::string& tmp) {
  for (auto& slot : g_in_flight) {
    char* p = slot.load();
    if (p && tmp == p && slot.compare_exchange_strong(p, nullptr)) {
      std::free(p);
      return;
    }
  }
}

// A signal during a commit's renames would leave some outputs new and the
// others old, so it waits for the last rename: the handler (on whichever
// thread the signal reaches) and the commit agree through one lock-free state.
enum CommitState : int { kIdle, kCommitting, kDying };
std::atomic<int> g_commit_state{kIdle};
std::atomic<int> g_deferred_signal{0};

extern "C" void remove_temporaries_and_reraise(int sig) {
  int idle = kIdle;
  if (!g_commit_state.compare_exchange_strong(idle, kDying)) {
    if (idle == kCommitting) {
      g_deferred_signal.store(sig);  // the commit raises it after its last rename
      return;
    }
  }
  for (auto& slot : g_in_flight)
    if (const char* p = slot.load()) ::unlink(p);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

struct Staged {
  std::string path, tmp;
  std::string content;  // an in-place target's (a device or FIFO): written at commit
  bool in_place = false;
};

// The file a path names, however it is spelled (relative, with . or ..), so
// that two outputs naming one file are seen to; the path itself when it
// cannot be resolved.
std::string file_identity(const std::string& path) {
  std::error_code e;
  // Absolute first: weakly_canonical leaves a relative path to a file that
  // does not exist yet relative, so x.png and $PWD/x.png would differ.
  const std::filesystem::path p =
      std::filesystem::weakly_canonical(std::filesystem::absolute(path, e), e);
  return e ? path : p.string();
}

// Where an output named `path` goes (docs/cli.md, "Output files"): a symbolic
// link is followed to the file it names, however many links deep, and that
// file is written (the link stays); a character device or a FIFO is written
// in place, never replaced; a block device, a socket or another kind of node
// is refused. What it finds, for the writers.
struct OutputTarget {
  std::string path;  // the file written: `path` itself, or where its links lead
  bool in_place = false;
};
OutputTarget output_target(const std::string& path) {
  std::filesystem::path p = path;
  for (int hops = 0;; ++hops) {
    struct stat st;
    if (::lstat(p.c_str(), &st) != 0) return {p.string(), false};  // nothing there yet
    if (S_ISLNK(st.st_mode)) {
      if (hops == 40)
        throw Error(fmt::format("cannot write '{}': too many levels of symbolic links", path));
      std::error_code e;
      const std::filesystem::path to = std::filesystem::read_symlink(p, e);
      if (e) throw Error(fmt::format("cannot write '{}': {}", path, e.message()));
      p = to.is_absolute() ? to : p.parent_path() / to;
      continue;
    }
    if (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode)) return {p.string(), false};
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return {p.string(), true};
    const char* kind = S_ISBLK(st.st_mode)    ? "a block device"
                       : S_ISSOCK(st.st_mode) ? "a socket"
                                              : "not a regular file";
    throw Error(fmt::format(
        "cannot write '{}': it is {}; aapat writes regular files (and devices and FIFOs in "
        "place), never replaces another node",
        path, kind));
  }
}

// Writes `content` into a device or FIFO as it is, without a temporary. A
// FIFO that no process reads is refused at once (opened without blocking),
// rather than waited on for ever.
void write_in_place(const std::string& path, std::string_view content) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int err = errno;
    throw Error(fmt::format(
        "cannot write '{}': {}", path,
        err == ENXIO ? "no process reads it (a FIFO without a reader)" : std::strerror(err)));
  }
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // then as a stream writes
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = errno;
      ::close(fd);
      throw Error(fmt::format("cannot write '{}': {}", path,
                              n < 0 ? std::strerror(err) : "nothing was written"));
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0)
    throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(errno)));
}

// The open transaction's state; guarded by g_mutex.
std::mutex g_mutex;
bool g_open = false;
std::vector<Staged> g_staged;
std::set<std::string> g_staged_files;     // file_identity of every staged path
std::vector<std::string> g_created_now;   // deleted on rollback
std::vector<std::string> g_created_dirs;  // removed on rollback when empty, deepest first
std::vector<std::string> g_removals;      // files removed at commit
std::atomic<unsigned long> g_counter{0};

std::string temporary_name(const std::string& path) {
  return fmt::format("{}.tmp.{}.{}", path, static_cast<long>(::getpid()), g_counter++);
}

void remove_temporary(const std::string& tmp) {
  std::remove(tmp.c_str());
  untrack_temporary(tmp);
}

// Writes the content beside the target; returns the temporary's name.
std::string write_temporary(const std::string& path, std::string_view content) {
  const std::string tmp = temporary_name(path);
  track_temporary(tmp);
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) {
    const int err = errno;
    untrack_temporary(tmp);
    throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  }
  out.write(content.data(), static_cast<std::streamsize>(content.size()));
  out.flush();
  if (!out) {
    out.close();
    remove_temporary(tmp);
    throw Error(fmt::format("cannot write '{}': write failed (disk full?)", path));
  }
  return tmp;
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    remove_temporary(tmp);
    throw Error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  }
  untrack_temporary(tmp);
}

bool exists(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0;
}

}  // namespace

std::atomic<bool> g_muted{false};

void mute_outputs() {
  g_muted = true;
}

void write_file_atomically(const std::string& path, std::string_view content) {
  if (g_muted) return;
  // What the rename at commit would refuse, refused now: before the command
  // reports the file as written, and before it stages the others.
  std::error_code e;
  if (std::filesystem::is_directory(path, e))
    throw Error(fmt::format("cannot write '{}': it is a folder", path));
  const OutputTarget target = output_target(path);
  const std::string file = file_identity(target.path);
  auto refuse_twice = [&] {
    throw Error(fmt::format("two outputs of this command name the same file '{}'", path));
  };
  {
    const std::lock_guard lock(g_mutex);
    if (g_open && g_staged_files.count(file)) refuse_twice();
  }
  if (target.in_place) {
    {
      const std::lock_guard lock(g_mutex);
      if (g_open) {
        if (!g_staged_files.insert(file).second) refuse_twice();
        g_staged.push_back({target.path, "", std::string(content), true});
        return;
      }
    }
    write_in_place(target.path, content);
    return;
  }
  const std::string tmp = write_temporary(target.path, content);
  {
    const std::lock_guard lock(g_mutex);
    if (g_open) {
      if (!g_staged_files.insert(file).second) {  // staged meanwhile by another thread
        remove_temporary(tmp);
        refuse_twice();
      }
      g_staged.push_back({target.path, tmp, {}, false});
      return;
    }
  }
  rename_into_place(tmp, target.path);
}

void write_file_now(const std::string& path, std::string_view content, bool keep_on_rollback) {
  if (g_muted) return;
  const OutputTarget target = output_target(path);
  if (target.in_place) return write_in_place(target.path, content);
  const bool existed = exists(target.path);
  const std::string tmp = write_temporary(target.path, content);
  rename_into_place(tmp, target.path);
  const std::lock_guard lock(g_mutex);
  if (g_open && !existed && !keep_on_rollback) g_created_now.push_back(target.path);
}

void ensure_directory(const std::string& path, std::string_view what) {
  if (g_muted) return;
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status))
      throw Error(fmt::format("{} '{}': exists and is not a folder", what, path));
  } else {
    // The folders this call makes, deepest first, for a rollback to remove.
    std::vector<std::string> made;
    for (std::filesystem::path p = std::filesystem::absolute(path, ec);
         !p.empty() && !std::filesystem::exists(p, ec); p = p.parent_path()) {
      made.push_back(p.string());
      if (p == p.parent_path()) break;
    }
    std::filesystem::create_directories(path, ec);
    if (ec) throw Error(fmt::format("{} '{}': cannot create it: {}", what, path, ec.message()));
    const std::lock_guard lock(g_mutex);
    if (g_open) g_created_dirs.insert(g_created_dirs.end(), made.begin(), made.end());
  }
  if (::access(path.c_str(), W_OK | X_OK) != 0)
    throw Error(fmt::format("{} '{}': cannot write into it: {}", what, path, std::strerror(errno)));
}

void check_directory_target(const std::string& path, std::string_view what) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return;
  if (!std::filesystem::is_directory(status))
    throw Error(fmt::format("{} '{}': exists and is not a folder", what, path));
  if (::access(path.c_str(), W_OK | X_OK) != 0)
    throw Error(fmt::format("{} '{}': cannot write into it: {}", what, path, std::strerror(errno)));
}

void check_file_target(const std::string& path, std::string_view what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(fmt::format("{} '{}': it is a folder, not a file", what, path));
  OutputTarget target;
  try {
    target = output_target(path);
  } catch (const Error& e) {
    throw Error(fmt::format("{}: {}", what, e.what()));
  }
  if (target.in_place) {  // a device or FIFO: written as it is, its folder untouched
    if (::access(target.path.c_str(), W_OK) != 0)
      throw Error(fmt::format("{} '{}': cannot write: {}", what, path, std::strerror(errno)));
    return;
  }
  if (target.path != path) return check_file_target(target.path, what);  // where links lead
  std::string folder = std::filesystem::path(path).parent_path().string();
  if (folder.empty()) folder = ".";
  const auto status = std::filesystem::status(folder, ec);
  if (!std::filesystem::exists(status))
    throw Error(fmt::format("{} '{}': the folder '{}' does not exist", what, path, folder));
  if (!std::filesystem::is_directory(status))
    throw Error(fmt::format("{} '{}': '{}' is not a folder", what, path, folder));
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw Error(fmt::format("{} '{}': cannot write into '{}': {}", what, path, folder,
                            std::strerror(errno)));
}

OutputTransaction::OutputTransaction() {
  const std::lock_guard lock(g_mutex);
  if (g_open) throw Error("internal: an output transaction is already open");
  g_open = true;
  g_staged.clear();
  g_staged_files.clear();
  g_created_now.clear();
  g_created_dirs.clear();
  g_removals.clear();
}

OutputTransaction::~OutputTransaction() {
  const std::lock_guard lock(g_mutex);
  if (!g_open) return;
  for (const Staged& s : g_staged)
    if (!s.in_place) remove_temporary(s.tmp);
  for (const std::string& path : g_created_now) std::remove(path.c_str());
  // Deepest first (longest path), so a parent is empty when its turn comes.
  std::sort(g_created_dirs.begin(), g_created_dirs.end(),
            [](const std::string& a, const std::string& b) { return a.size() > b.size(); });
  for (const std::string& dir : g_created_dirs) ::rmdir(dir.c_str());  // only if empty
  g_staged.clear();
  g_staged_files.clear();
  g_created_now.clear();
  g_created_dirs.clear();
  g_removals.clear();
  g_open = false;
}

void remove_orphaned_temporaries(const std::string& dir) {
  using namespace std::chrono_literals;
  std::error_code e;
  const auto now = std::filesystem::file_time_type::clock::now();
  for (const auto& entry : std::filesystem::directory_iterator(dir, e)) {
    // NAME.tmp.PID.N, as temporary_name writes them.
    const std::string name = entry.path().filename().string();
    const size_t tmp = name.rfind(".tmp.");
    if (tmp == std::string::npos) continue;
    const std::string rest = name.substr(tmp + 5);
    const size_t dot = rest.find('.');
    if (dot == std::string::npos || dot == 0 ||
        rest.find_first_not_of("0123456789.") != std::string::npos)
      continue;
    const long pid = std::strtol(rest.substr(0, dot).c_str(), nullptr, 10);
    if (pid <= 0 || pid == static_cast<long>(::getpid())) continue;
    // Its writer is gone (and the file is old enough that a writer on
    // another machine sharing the folder would have finished).
    const bool gone = ::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH;
    std::error_code age;
    const auto written = std::filesystem::last_write_time(entry.path(), age);
    if (gone && !age && now - written > 10min) std::filesystem::remove(entry.path(), e);
  }
}

void remove_file_at_commit(const std::string& path) {
  if (g_muted) return;
  {
    const std::lock_guard lock(g_mutex);
    if (g_open) {
      g_removals.push_back(path);
      return;
    }
  }
  std::remove(path.c_str());
}

void OutputTransaction::commit() {
  std::vector<Staged> staged;
  std::vector<std::string> removals;
  {
    const std::lock_guard lock(g_mutex);
    staged.swap(g_staged);
    removals.swap(g_removals);
    g_staged_files.clear();
    g_created_now.clear();
    g_created_dirs.clear();
    g_open = false;
  }
  int idle = kIdle;
  if (!g_commit_state.compare_exchange_strong(idle, kCommitting)) {
    // A signal is ending the process and removing the temporaries: rename
    // nothing, so that the old set stays whole.
    for (;;) pause();
  }
  // Every path is staged once (write_file_atomically refuses a second).
  std::exception_ptr failure;
  for (size_t i = 0; i < staged.size() && !failure; ++i) {
    try {
      if (staged[i].in_place)
        write_in_place(staged[i].path, staged[i].content);
      else
        rename_into_place(staged[i].tmp, staged[i].path);
    } catch (const Error&) {
      for (size_t j = i + 1; j < staged.size(); ++j)
        if (!staged[j].in_place) remove_temporary(staged[j].tmp);
      failure = std::current_exception();
    }
  }
  if (!failure)
    for (const std::string& path : removals) std::remove(path.c_str());
  g_commit_state.store(kIdle);
  if (const int sig = g_deferred_signal.exchange(0)) remove_temporaries_and_reraise(sig);
  if (failure) std::rethrow_exception(failure);
}

void remove_temporaries_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &action, nullptr);
}

}  // namespace aapat
