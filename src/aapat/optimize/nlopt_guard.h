// NLopt is C: an exception (an interrupt, a failed allocation, a bad value
// found inside an evaluation) must not unwind through its frames. Each
// callback runs its body through call(), which keeps the first exception and
// asks NLopt to stop; after nlopt_optimize returns, rethrow() raises it.
#pragma once

#include <nlopt.h>

#include <exception>
#include <utility>

#include "aapat/core/interrupt.h"

namespace aapat {

class NloptGuard {
 public:
  void attach(nlopt_opt opt) { opt_ = opt; }

  // Runs body() unless a failure is already kept; true when it ran to the end.
  template <class Body>
  bool call(Body&& body) noexcept {
    if (failure_) return false;
    try {
      throw_if_interrupted();
      std::forward<Body>(body)();
      return true;
    } catch (...) {
      failure_ = std::current_exception();
      if (opt_) nlopt_force_stop(opt_);
      return false;
    }
  }

  void rethrow() const {
    if (failure_) std::rethrow_exception(failure_);
  }

 private:
  nlopt_opt opt_ = nullptr;
  std::exception_ptr failure_;
};

}  // namespace aapat
