#include "cluster/mpi_engine.h"

#include <fmt/format.h>
#include <mpi.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

#include "aapat/core/geometry.h"
#include "aapat/work/byte_codec.h"

namespace aapat {
namespace {

using Clock = std::chrono::steady_clock;

// kRequest: a worker asks for its first items (how many it runs at once).
// kAssign: an item for a worker, or -1: no more. kResult: an item's result.
// kResults: every result of the set (or its failure), to every worker.
// kAbort: rank 0 failed; stop. kFinal: a worker's exit status at the end of
// the command. kVerdict: the status every rank exits with.
enum Tag : int { kRequest = 1, kAssign, kResult, kResults, kAbort, kFinal, kVerdict };

// How long an idle main thread sleeps between looks at MPI: from kIdle,
// doubling while nothing happens, up to kIdleMax. MPI's blocking calls spin,
// which would take a core from the items; each rank keeps items queued
// beyond its threads, so the longer sleeps cost no item time.
constexpr auto kIdle = std::chrono::microseconds(50);
constexpr auto kIdleMax = std::chrono::microseconds(3200);

class Backoff {
 public:
  std::chrono::microseconds next() {
    const auto now = sleep_;
    sleep_ = std::min(kIdleMax, sleep_ * 2);
    return now;
  }
  void reset() { sleep_ = kIdle; }

 private:
  std::chrono::microseconds sleep_ = kIdle;
};

void send(int to, Tag tag, const std::string& bytes) {
  if (bytes.size() > static_cast<size_t>(INT_MAX))
    throw Error(fmt::format("cluster: a message of {} bytes is too large", bytes.size()));
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

struct Message {
  int from = 0, tag = 0;
  std::string bytes;
};

Message receive(const MPI_Status& probed) {
  int count = 0;
  MPI_Get_count(&probed, MPI_BYTE, &count);
  Message m{probed.MPI_SOURCE, probed.MPI_TAG, std::string(static_cast<size_t>(count), '\0')};
  MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.from, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

std::optional<Message> poll(int source) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return std::nullopt;
  return receive(status);
}

Message wait_for_message(int source) {
  Backoff backoff;
  while (true) {
    if (auto m = poll(source)) return std::move(*m);
    std::this_thread::sleep_for(backoff.next());
  }
}

// Every result of a set can pass MPI's int count: sent as its size, then
// pieces of at most 1 GiB.
constexpr size_t kPiece = size_t{1} << 30;
void send_all(int to, const std::string& bytes) {
  ByteWriter size;
  size.put<uint64_t>(bytes.size());
  send(to, kResults, size.take());
  for (size_t at = 0; at < bytes.size(); at += kPiece)
    send(to, kResults, bytes.substr(at, std::min(kPiece, bytes.size() - at)));
}
std::string receive_all(const Message& size_message) {
  ByteReader r(size_message.bytes);
  const auto size = r.get<uint64_t>();
  std::string bytes;
  bytes.reserve(size);
  while (bytes.size() < size) {
    MPI_Status status;
    MPI_Probe(0, kResults, MPI_COMM_WORLD, &status);
    bytes += receive(status).bytes;
  }
  return bytes;
}

}  // namespace

// This rank's item threads: an arena whose slots are all for workers, so the
// items run while the main thread talks MPI.
struct MpiEngine::Local {
  struct Done {
    int item = 0;
    bool ok = false;
    std::string bytes;  // the result, or the error's message
    double seconds = 0;
  };
  explicit Local(int slots) : slots(slots), arena(slots, 0) {}
  // Items in the arena at once: one more than its threads, so a thread that
  // ends an item starts the next without waiting for the main thread.
  int ahead() const { return slots + 1; }

  void launch(const ItemWork& work, int item) {
    ++in_flight;
    arena.enqueue([this, &work, item] {
      const auto t0 = Clock::now();
      Done d{item, false, {}, 0};
      try {
        d.bytes = work(item);
        d.ok = true;
      } catch (const std::exception& e) {
        d.bytes = e.what();
      } catch (...) {
        d.bytes = "an unknown error";
      }
      d.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      {
        const std::lock_guard lock(mutex);
        done.push_back(std::move(d));
      }
      wake.notify_one();
    });
  }
  std::deque<Done> take() {
    std::deque<Done> out;
    const std::lock_guard lock(mutex);
    out.swap(done);
    in_flight -= static_cast<int>(out.size());
    return out;
  }
  // Until an item ends or `sleep` passes.
  void wait(std::chrono::microseconds sleep = kIdle) {
    std::unique_lock lock(mutex);
    wake.wait_for(lock, sleep, [&] { return !done.empty(); });
  }
  // Waits for the items in flight (they reference the caller's work) and
  // drops their results.
  void drain() {
    while (in_flight > 0) {
      wait();
      take();
    }
  }

  int slots;
  tbb::task_arena arena;
  std::mutex mutex;
  std::condition_variable wake;
  std::deque<Done> done;
  int in_flight = 0;  // main thread only
};

MpiEngine::MpiEngine() {
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  busy_.assign(static_cast<size_t>(size_), 0.0);
  items_.assign(static_cast<size_t>(size_), 0);
  final_seen_.assign(static_cast<size_t>(size_), false);
}

MpiEngine::~MpiEngine() = default;

void MpiEngine::run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
                    const Finished& finished) {
  if (!local_) {
    // The command's thread limit counts this (main) thread: the rest run items.
    const int limit = static_cast<int>(
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
    local_ = std::make_unique<Local>(std::max(1, limit - service_threads()));
  }
  try {
    if (rank_ == 0) {
      run_root(results, work, finished);
    } else {
      run_worker(results, work);
    }
  } catch (...) {
    local_->drain();  // the items in flight use the caller's work
    throw;
  }
}

void MpiEngine::run_root(std::vector<std::optional<std::string>>& results, const ItemWork& work,
                         const Finished& finished) {
  const auto t0 = Clock::now();
  Local& local = *local_;
  std::deque<int> pending;
  for (size_t i = 0; i < results.size(); ++i)
    if (!results[i]) pending.push_back(static_cast<int>(i));
  std::vector<int> outstanding(static_cast<size_t>(size_), 0);   // handed out, not back
  std::vector<bool> stopped(static_cast<size_t>(size_), false);  // told: no more
  stopped[0] = true;
  for (int r = 1; r < size_; ++r) stopped[r] = final_seen_[r];
  std::optional<std::pair<int, std::string>> failure;  // the lowest failing item
  std::string left;  // a rank that ended the command with an error
  const auto handing_out = [&] { return !pending.empty() && !failure && left.empty(); };
  const auto hand_to = [&](int w) {
    if (stopped[w]) return;
    int item = -1;
    if (handing_out()) {
      item = pending.front();
      pending.pop_front();
      ++outstanding[w];
    } else {
      stopped[w] = true;
    }
    ByteWriter b;
    b.put<int32_t>(item);
    send(w, kAssign, b.take());
  };
  const auto accept = [&](int from, Local::Done d) {
    --outstanding[from];
    longest_ = std::max(longest_, d.seconds);
    busy_[from] += d.seconds;
    ++items_[from];
    if (!d.ok) {
      if (!failure || d.item < failure->first) failure = {d.item, std::move(d.bytes)};
      return;
    }
    try {
      if (finished) finished(d.item, d.bytes);
    } catch (const std::exception& e) {  // the checkpoint could not be written
      failure = {-1, e.what()};
    }
    results[static_cast<size_t>(d.item)] = std::move(d.bytes);
  };
  Backoff backoff;
  while (true) {
    bool active = false;
    while (local.in_flight < local.ahead() && handing_out()) {
      ++outstanding[0];
      local.launch(work, pending.front());
      pending.pop_front();
      active = true;
    }
    for (Local::Done& d : local.take()) {
      accept(0, std::move(d));
      active = true;
    }
    while (auto m = poll(MPI_ANY_SOURCE)) {
      active = true;
      ByteReader r(m->bytes);
      if (m->tag == kRequest) {
        const int count = r.get<int32_t>();
        for (int k = 0; k < count; ++k) hand_to(m->from);
      } else if (m->tag == kResult) {
        Local::Done d;
        d.item = r.get<int32_t>();
        d.ok = r.get<uint8_t>() != 0;
        const bool wants_more = r.get<uint8_t>() != 0;
        d.seconds = r.get<double>();
        d.bytes = r.get_text();
        accept(m->from, std::move(d));
        if (wants_more) hand_to(m->from);
      } else if (m->tag == kFinal) {
        // A rank ended the command (it failed before reaching these items).
        const int status = r.get<int32_t>();
        std::string why = r.get_text();
        if (status == 0)
          why = "it ended without these work items (was every rank given the same command?)";
        final_seen_[m->from] = true;
        finals_.push_back({m->from, status == 0 ? 1 : status, why});
        if (left.empty()) left = fmt::format("rank {}: {}", m->from, why);
        outstanding[m->from] = 0;
        stopped[m->from] = true;
      } else {
        throw Error(fmt::format("cluster: unexpected message {} from rank {}", m->tag, m->from));
      }
    }
    const bool all_back =
        std::all_of(outstanding.begin(), outstanding.end(), [](int n) { return n == 0; });
    const bool all_stopped = std::all_of(stopped.begin(), stopped.end(), [](bool b) { return b; });
    if (!handing_out() && all_back && all_stopped) break;
    if (active) {
      backoff.reset();
    } else {
      local.wait(backoff.next());
    }
  }
  wall_ += std::chrono::duration<double>(Clock::now() - t0).count();
  if (!left.empty()) throw Error(left);
  ByteWriter w;
  w.put<uint8_t>(failure ? 1 : 0);
  if (failure) {
    w.put_text(failure->second);
  } else {
    for (const auto& r : results) w.put_text(*r);
  }
  const std::string all = w.take();
  for (int to = 1; to < size_; ++to)
    if (!final_seen_[to]) send_all(to, all);
  if (failure) throw Error(failure->second);
}

void MpiEngine::run_worker(std::vector<std::optional<std::string>>& results, const ItemWork& work) {
  Local& local = *local_;
  {
    ByteWriter b;
    b.put<int32_t>(local.ahead() + 1);  // and one waiting here for the next free thread
    send(0, kRequest, b.take());
  }
  std::deque<int> queued;
  bool stop = false;
  Backoff backoff;
  while (true) {
    bool active = false;
    for (Local::Done& d : local.take()) {
      ByteWriter b;
      b.put<int32_t>(d.item).put<uint8_t>(d.ok ? 1 : 0).put<uint8_t>(stop ? 0 : 1).put(d.seconds);
      b.put_text(d.bytes);
      send(0, kResult, b.take());
      active = true;
    }
    while (auto m = poll(0)) {
      active = true;
      if (m->tag == kAssign) {
        const int item = ByteReader(m->bytes).get<int32_t>();
        if (item < 0) {
          stop = true;
        } else {
          queued.push_back(item);
        }
      } else if (m->tag == kAbort) {
        local.drain();
        throw Error("stopped: another rank failed");
      } else if (m->tag == kResults) {
        const std::string all = receive_all(*m);
        ByteReader r(all);
        if (r.get<uint8_t>() != 0) throw Error(r.get_text());
        for (auto& result : results) result = r.get_text();
        r.finish();
        return;
      } else {
        throw Error(fmt::format("cluster: unexpected message {} from rank 0", m->tag));
      }
    }
    while (local.in_flight < local.ahead() && !queued.empty()) {
      local.launch(work, queued.front());
      queued.pop_front();
      active = true;
    }
    if (active) {
      backoff.reset();
    } else {
      local.wait(backoff.next());
    }
  }
}

int MpiEngine::agree(int status, std::string& message) {
  if (rank_ != 0) {
    ByteWriter b;
    b.put<int32_t>(status).put_text(message);
    send(0, kFinal, b.take());
    while (true) {  // what rank 0 sent before it knew is dropped
      const Message m = wait_for_message(0);
      if (m.tag == kVerdict) return ByteReader(m.bytes).get<int32_t>();
    }
  }
  if (status != 0)
    for (int to = 1; to < size_; ++to)
      if (!final_seen_[to]) send(to, kAbort, {});
  int verdict = status;
  for (int from = 1; from < size_; ++from) {
    int their = 1;
    std::string why;
    if (final_seen_[from]) {
      for (const Final& f : finals_)
        if (f.rank == from) {
          their = f.status;
          why = f.why;
        }
    } else {
      while (true) {  // requests and results of a set rank 0 left are dropped
        const Message m = wait_for_message(from);
        if (m.tag != kFinal) continue;
        ByteReader r(m.bytes);
        their = r.get<int32_t>();
        why = r.get_text();
        break;
      }
    }
    if (verdict == 0 && their != 0) {
      verdict = their;
      message = fmt::format("rank {}: {}", from, why);
    }
  }
  ByteWriter b;
  b.put<int32_t>(verdict);
  const std::string word = b.take();
  for (int to = 1; to < size_; ++to) send(to, kVerdict, word);
  return verdict;
}

std::string MpiEngine::report() const {
  if (rank_ != 0) return {};
  std::string text = fmt::format(
      "aapat: {} ranks, {:.2f} s in work items (the longest {:.3f} s); busy (seconds inside "
      "items, all threads):",
      size_, wall_, longest_);
  for (int r = 0; r < size_; ++r)
    text += fmt::format(" rank {} {:.2f} s ({} items){}", r, busy_[r], items_[r],
                        r + 1 < size_ ? "," : "\n");
  return text;
}

}  // namespace aapat
