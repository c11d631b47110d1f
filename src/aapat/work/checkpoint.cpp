#include "aapat/work/checkpoint.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "aapat/core/geometry.h"
#include "aapat/core/hash.h"

namespace aapat {
namespace {

// Version 2: a record's checksum covers its set and index as well as its
// bytes (version 1's covered the bytes alone, so swapped indices passed).
constexpr std::string_view kMagic = "aapat-checkpoint 2\n";
constexpr std::string_view kAnyVersion = "aapat-checkpoint ";

uint64_t record_sum(int call, int item, std::string_view bytes) {
  return fnv1a(fmt::format("{} {} {}", call, item, bytes));
}

// The command on one line: newlines in arguments would end it early.
std::string one_line(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// Reads the records after the header; returns where the last whole one ends.
size_t read_records(const std::string& data, size_t at,
                    std::map<std::pair<int, int>, std::string>& items, std::map<int, int>& counts) {
  while (at < data.size()) {
    const size_t eol = data.find('\n', at);
    if (eol == std::string::npos) break;
    int call = 0, item = 0;
    unsigned long long size = 0, sum = 0;
    std::istringstream head(data.substr(at, eol - at));
    std::string word;
    if (!(head >> word)) break;
    if (word == "set") {  // "set CALL COUNT"
      if (!(head >> call >> item)) break;
      counts[call] = item;
      at = eol + 1;
      continue;
    }
    if (!(head >> call >> item >> size >> std::hex >> sum) || word != "item") break;
    const size_t begin = eol + 1;
    if (size > data.size() || begin + size + 1 > data.size() || data[begin + size] != '\n') break;
    const std::string_view bytes(data.data() + begin, size);
    if (record_sum(call, item, bytes) != sum) break;
    items[{call, item}] = std::string(bytes);
    at = begin + size + 1;
  }
  return at;
}

}  // namespace

Checkpoint::Checkpoint(std::string path, std::string fingerprint) : path_(std::move(path)) {
  const std::string header = fmt::format("{}command {}\n", kMagic, one_line(fingerprint));
  std::error_code ec;
  size_t keep = 0;
  if (std::filesystem::exists(path_, ec)) {
    if (!std::filesystem::is_regular_file(path_, ec))
      throw Error(fmt::format("--checkpoint {}: not a regular file", path_));
    std::ifstream in(path_, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.eof() && in.fail()) throw Error(fmt::format("--checkpoint {}: cannot be read", path_));
    if (!data.empty()) {
      if (data.compare(0, kMagic.size(), kMagic) != 0) {
        if (data.compare(0, kAnyVersion.size(), kAnyVersion) == 0)
          throw Error(fmt::format(
              "--checkpoint {}: written by another version of aapat (an older record format); "
              "delete it or name another file",
              path_));
        throw Error(fmt::format(
            "--checkpoint {}: not an aapat checkpoint (refusing to overwrite it)", path_));
      }
      if (data.compare(0, header.size(), header) != 0) {
        const size_t from =
            std::min(data.size(), kMagic.size() + std::string_view("command ").size());
        const std::string other = data.substr(from, data.find('\n', from) - from);
        throw Error(fmt::format(
            "--checkpoint {}: it belongs to another command ('{}'); resume with that command, or "
            "delete the file or name another one",
            path_, other));
      }
      keep = read_records(data, header.size(), items_, counts_);
      restored_ = static_cast<int>(items_.size());
      // A record cut off by the kill is dropped before new ones follow it.
      std::filesystem::resize_file(path_, keep, ec);
      if (ec) throw Error(fmt::format("--checkpoint {}: {}", path_, ec.message()));
    }
  }
  file_ = std::fopen(path_.c_str(), "ab");
  if (!file_)
    throw Error(fmt::format("--checkpoint {}: cannot be written: {}", path_, std::strerror(errno)));
  if (keep == 0) {
    try {
      append({header});
    } catch (...) {  // no destructor runs for a constructor that throws
      std::fclose(file_);
      throw;
    }
  }
}

Checkpoint::~Checkpoint() {
  if (file_) std::fclose(file_);
}

void Checkpoint::begin(int call, int count) {
  if (const auto it = counts_.find(call); it != counts_.end()) {
    if (it->second != count)
      throw Error(fmt::format(
          "--checkpoint {}: the run's set {} of work items has {} items, the checkpoint's {}: it "
          "was written by another path through the command (another aapat version, or a time "
          "limit); delete it or name another file",
          path_, call + 1, count, it->second));
    return;
  }
  counts_[call] = count;
  const std::string line = fmt::format("set {} {}\n", call, count);
  append({line});
}

std::optional<std::string> Checkpoint::find(int call, int item) const {
  const auto it = items_.find({call, item});
  if (it == items_.end()) return std::nullopt;
  return it->second;
}

void Checkpoint::record(int call, int item, std::string_view result) {
  const std::string head = fmt::format("item {} {} {} {:x}\n", call, item, result.size(),
                                       record_sum(call, item, result));
  append({head, result, "\n"});
}

void Checkpoint::append(std::initializer_list<std::string_view> pieces) {
  bool written = true;
  for (const std::string_view piece : pieces)
    written = std::fwrite(piece.data(), 1, piece.size(), file_) == piece.size() && written;
  if (std::fflush(file_) != 0 || !written)
    throw Error(fmt::format("--checkpoint {}: cannot be written: {}", path_, std::strerror(errno)));
}

}  // namespace aapat
