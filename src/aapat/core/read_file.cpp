#include "aapat/core/read_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "aapat/core/geometry.h"

namespace aapat {

std::string read_file(const std::string& path, std::string_view what, size_t max_bytes) {
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
  return s.str();
}

}  // namespace aapat
