#include "aapat/work/work_items.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <climits>
#include <exception>
#include <mutex>
#include <thread>

#include "aapat/core/geometry.h"
#include "aapat/core/interrupt.h"
#include "aapat/work/checkpoint.h"

namespace aapat {
namespace {

// Items being run by this thread: a call made inside one runs locally.
thread_local int t_item_depth = 0;
struct InsideItem {
  InsideItem() { ++t_item_depth; }
  ~InsideItem() { --t_item_depth; }
};

struct Session {
  WorkEngine* engine = nullptr;
  Checkpoint* checkpoint = nullptr;
  std::thread::id thread;
  int calls = 0;  // the sets of items run so far: the checkpoint's call numbers
};
Session* g_session = nullptr;

}  // namespace

void LocalEngine::run(std::vector<std::optional<std::string>>& results, const ItemWork& work,
                      const Finished& finished) {
  std::vector<int> missing;
  for (size_t i = 0; i < results.size(); ++i)
    if (!results[i]) missing.push_back(static_cast<int>(i));
  std::mutex mutex;
  std::vector<std::exception_ptr> errors(results.size());
  // Past the lowest failing item nothing new starts; below it every item
  // runs, so the error reported is the same whatever the timing.
  std::atomic<int> first_failure{INT_MAX};
  tbb::parallel_for(size_t{0}, missing.size(), [&](size_t k) {
    const int i = missing[k];
    if (i > first_failure || interrupt_requested()) return;
    try {
      std::string result = work(i);
      const std::lock_guard lock(mutex);
      if (finished) finished(i, result);
      results[static_cast<size_t>(i)] = std::move(result);
    } catch (...) {
      errors[static_cast<size_t>(i)] = std::current_exception();
      int seen = first_failure;
      while (i < seen && !first_failure.compare_exchange_weak(seen, i)) {
      }
    }
  });
  throw_if_interrupted();  // before the items' errors: an interrupted item may have failed
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

std::vector<std::string> run_work_items(int count, const ItemWork& work,
                                        const ItemsProgress& progress) {
  if (count < 0) throw Error(fmt::format("work items: a count of {} items", count));
  std::vector<std::optional<std::string>> results(static_cast<size_t>(count));
  Session* session = g_session;
  const bool top = session && t_item_depth == 0 && std::this_thread::get_id() == session->thread;
  const int call = top ? session->calls++ : -1;
  Checkpoint* checkpoint = top ? session->checkpoint : nullptr;
  int done = 0;
  if (checkpoint) {
    checkpoint->begin(call, count);
    for (int i = 0; i < count; ++i)
      if (auto& r = results[static_cast<size_t>(i)]; (r = checkpoint->find(call, i))) {
        ++done;
        if (progress) progress(done, count, *r);
      }
  }
  const WorkEngine::Finished finished = [&](int item, const std::string& result) {
    if (checkpoint && !result.empty()) checkpoint->record(call, item, result);
    ++done;
    if (progress) progress(done, count, result);
  };
  // Whichever thread runs an item, a call inside it runs locally.
  const ItemWork item = [&work](int i) {
    const InsideItem inside;
    return work(i);
  };
  if (top) {
    session->engine->run(results, item, finished);
  } else {
    LocalEngine().run(results, item, finished);
  }
  std::vector<std::string> out;
  out.reserve(results.size());
  for (auto& r : results) out.push_back(std::move(r.value()));
  return out;
}

std::string run_as_one_item(const std::function<std::string()>& work) {
  return run_work_items(1, [&](int) { return work(); }).front();
}

WorkSession::WorkSession(WorkEngine& engine, Checkpoint* checkpoint) {
  if (g_session) throw Error("work items: a session is already open");
  g_session = new Session{&engine, checkpoint, std::this_thread::get_id(), 0};
}

WorkSession::~WorkSession() {
  delete g_session;
  g_session = nullptr;
}

void check_threads(int threads, std::string_view what) {
  if (threads < 0 || threads > kMaxThreads)
    throw Error(fmt::format("{}: {} is not in [0, {}] (0: all cores)", what, threads, kMaxThreads));
}

}  // namespace aapat
