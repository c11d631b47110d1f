// Warnings the library gives while it reads or computes (a file renamed
// because its name was a catalog entry's): handed to one handler, by default
// "aapat: warning: ..." on stderr, as the command line prints its own.
#pragma once

#include <functional>
#include <string>

namespace aapat {

using WarningHandler = std::function<void(const std::string&)>;

// Gives `message` to the current handler.
void warn(const std::string& message);

// Replaces the handler (Python turns warnings into Python warnings); returns
// the previous one. An empty handler restores the default.
WarningHandler set_warning_handler(WarningHandler handler);

}  // namespace aapat
