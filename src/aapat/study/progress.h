// How a long job reports where it is: (done, total, a short note). The
// library never prints; the command line draws a bar from these calls, the
// Python module forwards them to a callable.
#pragma once

#include <functional>
#include <string>

namespace aapat {

using StudyProgress = std::function<void(int done, int total, const std::string& note)>;

}  // namespace aapat
