// Every file input read by one function (the acuity tables here, pattern,
// point, scene, sequence, texture and image files above): a regular file of
// bounded size, checked before a byte is read, so that a FIFO, a device
// (/dev/zero) or a folder is refused by name instead of blocking or
// filling memory.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace aapat {

// Reads a whole regular file of at most `max_bytes`; the message names `what`,
// the path and the reason (missing, a folder, not a regular file, too large,
// unreadable).
inline constexpr size_t kMaxInputFileBytes = size_t{256} << 20;
std::string read_file(const std::string& path, std::string_view what,
                      size_t max_bytes = kMaxInputFileBytes);

}  // namespace aapat
