#include "aapat/work/checkpoint.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/hash.h"
#include "aapat/core/read_file.h"

namespace aapat {
namespace {

// Version 2: a record's checksum covers its set and index as well as its
// bytes (version 1's covered the bytes alone, so swapped indices passed).
// Version 3: each set of work items also records the input files read before
// it began (core/read_file.h), so a changed texture inside a scene file is
// seen, not only the files named on the command line. Version 4: the
// record checksums are true FNV-1a (the offset basis had lost its last
// digit), and the input files' contents are summed with checksum64.
// Version 5: a reference's items are bands of 32 rows, summed pixel by pixel
// (render/reference.cpp), where version 4's were 8 rows with other last bits.
constexpr std::string_view kMagic = "aapat-checkpoint 5\n";
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

// "PATH BYTES SUM" of every input read, one after another, on one line.
std::string inputs_text() {
  std::string text;
  for (const InputRead& r : inputs_read())
    text +=
        fmt::format("{}{} {} {:016x}", text.empty() ? "" : "\t", one_line(r.path), r.bytes, r.sum);
  return text;
}

// What differs between two inputs_text()s, for the message: the paths whose
// digest changed, that are read now and were not, or the other way round.
std::string changed_inputs(std::string_view before, std::string_view now) {
  auto entries = [](std::string_view text) {
    std::map<std::string, std::string> out;
    size_t at = 0;
    while (at < text.size()) {
      size_t end = text.find('\t', at);
      if (end == std::string_view::npos) end = text.size();
      const std::string_view e = text.substr(at, end - at);
      const size_t digest = e.rfind(' ', e.rfind(' ') - 1);
      out[std::string(e.substr(0, digest))] = std::string(e.substr(digest + 1));
      at = end + 1;
    }
    return out;
  };
  const auto a = entries(before), b = entries(now);
  std::vector<std::string> notes;
  for (const auto& [path, digest] : b) {
    const auto it = a.find(path);
    if (it == a.end())
      notes.push_back(fmt::format("'{}' is read now and was not", path));
    else if (it->second != digest)
      notes.push_back(fmt::format("'{}' changed", path));
  }
  for (const auto& [path, digest] : a)
    if (!b.contains(path)) notes.push_back(fmt::format("'{}' is no longer read", path));
  return fmt::format("{}", fmt::join(notes, ", "));
}

// Reads the records after the header; returns where the last whole one ends.
size_t read_records(const std::string& data, size_t at,
                    std::map<std::pair<int, int>, std::string>& items, std::map<int, int>& counts,
                    std::map<int, std::string>& inputs) {
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
    if (word == "inputs") {  // "inputs CALL SUM TEXT": the inputs read before set CALL began
      if (!(head >> call >> std::hex >> sum >> std::dec)) break;
      std::string text;
      std::getline(head, text);
      if (!text.empty() && text.front() == ' ') text.erase(0, 1);
      if (record_sum(call, -1, text) != sum) break;
      inputs[call] = text;
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
      keep = read_records(data, header.size(), items_, counts_, inputs_);
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
  const std::string inputs = inputs_text();
  if (const auto it = inputs_.find(call); it != inputs_.end() && it->second != inputs)
    throw Error(fmt::format(
        "--checkpoint {}: the files the run read have changed since it was written ({}); "
        "delete it or name another file",
        path_, changed_inputs(it->second, inputs)));
  if (const auto it = counts_.find(call); it != counts_.end()) {
    if (it->second != count)
      throw Error(fmt::format(
          "--checkpoint {}: the run's set {} of work items has {} items, the checkpoint's {}: it "
          "was written by another path through the command (another aapat version, or a time "
          "limit); delete it or name another file",
          path_, call + 1, count, it->second));
    if (inputs_.contains(call)) return;
  }
  std::string lines;
  if (!inputs_.contains(call)) {
    inputs_[call] = inputs;
    lines += fmt::format("inputs {} {:x} {}\n", call, record_sum(call, -1, inputs), inputs);
  }
  if (!counts_.contains(call)) {
    counts_[call] = count;
    lines += fmt::format("set {} {}\n", call, count);
  }
  append({lines});
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
