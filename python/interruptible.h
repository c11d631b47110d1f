// Runs a long library call so that Ctrl-C ends it within a fraction of a
// second, with or without a progress callback: the call runs on a helper
// thread with the GIL released while the calling thread wakes every 20 ms,
// takes the GIL and lets Python run its signal handlers. When a handler
// raises (KeyboardInterrupt), the library is asked to stop
// (aapat::request_interrupt; its loops check between steps), the helper is
// joined, and the Python exception is raised here. Signals are only seen on
// the main thread, as everywhere in Python.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>

#include "aapat/core/interrupt.h"

namespace aapat::python {

template <class Work>
auto interruptible(Work&& work) -> std::invoke_result_t<Work&> {
  namespace py = pybind11;
  using Result = std::invoke_result_t<Work&>;
  using Stored = std::conditional_t<std::is_void_v<Result>, bool, Result>;
  std::optional<Stored> result;
  std::exception_ptr failure;
  std::optional<py::error_already_set> signalled;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  {
    py::gil_scoped_release release;
    std::thread helper([&] {
      try {
        if constexpr (std::is_void_v<Result>) {
          work();
          result.emplace(true);
        } else {
          result.emplace(work());
        }
      } catch (...) {
        failure = std::current_exception();
      }
      std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock lock(mutex);
    while (!done) {
      if (finished.wait_for(lock, std::chrono::milliseconds(20), [&] { return done; })) break;
      if (signalled) continue;  // asked already: wait for the helper to stop
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {
          signalled.emplace();  // takes the pending Python exception
          request_interrupt();
        }
      }
      lock.lock();
    }
    lock.unlock();
    helper.join();
  }
  if (signalled) {
    clear_interrupt();
    throw std::move(*signalled);
  }
  if (failure) std::rethrow_exception(failure);
  if constexpr (!std::is_void_v<Result>) return std::move(*result);
}

}  // namespace aapat::python
