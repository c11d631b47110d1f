#include "aapat/core/warning.h"

#include <iostream>
#include <mutex>

namespace aapat {
namespace {

std::mutex lock;
WarningHandler& handler() {
  static WarningHandler h;
  return h;
}

}  // namespace

void warn(const std::string& message) {
  WarningHandler h;
  {
    std::lock_guard<std::mutex> hold(lock);
    h = handler();
  }
  if (h)
    h(message);
  else
    std::cerr << "aapat: warning: " << message << "\n";
}

WarningHandler set_warning_handler(WarningHandler h) {
  std::lock_guard<std::mutex> hold(lock);
  WarningHandler previous = handler();
  handler() = std::move(h);
  return previous;
}

}  // namespace aapat
