#include "aapat/core/read_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include "aapat/core/geometry.h"
#include "aapat/core/hash.h"

namespace aapat {
namespace {

std::mutex inputs_mutex;
std::map<std::string, InputRead>& inputs() {
  static std::map<std::string, InputRead> kInputs;
  return kInputs;
}

}  // namespace

std::string read_file(const std::string& path, std::string_view what, size_t max_bytes,
                      bool note_input) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw Error(fmt::format("cannot read {} '{}': no such file", what, path));
  if (std::filesystem::is_directory(status))
    throw Error(fmt::format("cannot read {} '{}': it is a folder, not a file", what, path));
  if (!std::filesystem::is_regular_file(status))
    throw Error(fmt::format("cannot read {} '{}': not a regular file", what, path));
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes)
    throw Error(fmt::format("cannot read {} '{}': {} bytes exceed the limit of {} bytes", what,
                            path, size, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot read {} '{}': {}", what, path, std::strerror(errno)));
  std::ostringstream s;
  s << in.rdbuf();
  if (in.bad()) throw Error(fmt::format("cannot read {} '{}': read failed", what, path));
  std::string bytes = s.str();
  if (note_input) {
    const std::lock_guard<std::mutex> lock(inputs_mutex);
    inputs()[path] = {path, bytes.size(), checksum64(bytes)};
  }
  return bytes;
}

void forget_inputs_read() {
  const std::lock_guard<std::mutex> lock(inputs_mutex);
  inputs().clear();
}

std::vector<InputRead> inputs_read() {
  const std::lock_guard<std::mutex> lock(inputs_mutex);
  std::vector<InputRead> out;
  for (const auto& [path, read] : inputs()) out.push_back(read);
  return out;
}

}  // namespace aapat
