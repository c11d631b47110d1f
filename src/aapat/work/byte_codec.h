// Results of work items as bytes (work/work_items.h): what a process sends
// another and what a checkpoint keeps. Numbers are copied bit for bit, so a
// result decoded anywhere is the result computed, to the last bit.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

class ByteWriter {
 public:
  template <class T>
  requires std::is_arithmetic_v<T> ByteWriter& put(T value) {
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof value);
    return *this;
  }
  ByteWriter& put_text(std::string_view text) {
    put<uint64_t>(text.size());
    bytes_.append(text);
    return *this;
  }
  template <class T>
  ByteWriter& put_all(const std::vector<T>& values) {
    put<uint64_t>(values.size());
    if (!values.empty())  // an empty vector's data() may be null
      bytes_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    return *this;
  }
  std::string take() { return std::move(bytes_); }

 private:
  std::string bytes_;
};

// Reads what a ByteWriter wrote, in the same order; a short or long buffer is
// an Error (a result from another version, or a damaged checkpoint).
class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  requires std::is_arithmetic_v<T> T get() {
    T value;
    std::memcpy(&value, take(sizeof value), sizeof value);
    return value;
  }
  std::string get_text() {
    const auto n = get<uint64_t>();
    return std::string(take(n), n);
  }
  template <class T>
  std::vector<T> get_all() {
    const auto n = get<uint64_t>();
    if (n > bytes_.size() / sizeof(T)) fail();
    std::vector<T> values(n);
    if (n > 0) std::memcpy(values.data(), take(n * sizeof(T)), n * sizeof(T));
    return values;
  }
  // Throws unless everything was read.
  void finish() const {
    if (!bytes_.empty()) fail();
  }

 private:
  const char* take(size_t n) {
    if (n > bytes_.size()) fail();
    const char* at = bytes_.data();
    bytes_.remove_prefix(n);
    return at;
  }
  [[noreturn]] static void fail() {
    throw Error("a work item's result does not have the expected size (another aapat version?)");
  }
  std::string_view bytes_;
};

}  // namespace aapat
