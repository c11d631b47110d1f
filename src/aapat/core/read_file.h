// Every file input read by one function (the acuity tables here, pattern,
// point, scene, sequence, texture and image files above): a regular file of
// bounded size, checked before a byte is read, so that a FIFO, a device
// (/dev/zero) or a folder is refused by name instead of blocking or
// filling memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace aapat {

// Reads a whole regular file of at most `max_bytes`; the message names `what`,
// the path and the reason (missing, a folder, not a regular file, too large,
// unreadable).
// Each file read is also noted in inputs_read(), unless `note_input` is false
// (a cache entry: not an input of the command).
inline constexpr size_t kMaxInputFileBytes = size_t{256} << 20;
std::string read_file(const std::string& path, std::string_view what,
                      size_t max_bytes = kMaxInputFileBytes, bool note_input = true);

// Every input file this process has read, by path (the last read of each),
// with its size and checksum64: what a checkpoint binds itself to
// (work/checkpoint.h), however the command reached the file (a texture named
// inside a scene file, a model's images).
struct InputRead {
  std::string path;
  size_t bytes = 0;
  uint64_t sum = 0;
  friend bool operator==(const InputRead&, const InputRead&) = default;
};
std::vector<InputRead> inputs_read();
// Starts the list afresh: a command run in a process that ran others (the
// tests, a host program) is bound to its own inputs only.
void forget_inputs_read();

}  // namespace aapat
