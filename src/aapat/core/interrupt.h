// A request, from outside a long call, that it stop: Ctrl-C heard by the
// Python module's watcher, a cancel in a host application. Long loops call
// throw_if_interrupted() between steps of at most a few milliseconds, so the
// call ends within a fraction of a second with Interrupted, and whatever it
// was writing is abandoned (outputs are committed only after the work).
// The request is process-wide: it stops every call running when it is made,
// until clear_interrupt().
#pragma once

#include "aapat/core/geometry.h"

namespace aapat {

class Interrupted : public Error {
 public:
  Interrupted() : Error("interrupted") {}
};

void request_interrupt() noexcept;
void clear_interrupt() noexcept;
bool interrupt_requested() noexcept;

// Throws Interrupted when a request is pending (one relaxed atomic load).
inline void throw_if_interrupted() {
  if (interrupt_requested()) throw Interrupted();
}

}  // namespace aapat
