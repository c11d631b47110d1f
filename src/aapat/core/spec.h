// Specs: how filters, acuity tables, point generators, scenes, catalog
// patterns and API profiles are named, `name:key=value,...` (values are
// numbers or fractions, "1/3"). One registry shape serves every kind: its
// entries describe themselves (SpecInfo: name, summary, source, parameters
// with defaults), so `aapat list`, the docs and the Python module read the
// same lists the parsers use, and every parser refuses an unknown name or
// parameter the same way, naming the spec and what it takes.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace aapat {

struct ParamInfo {
  std::string key;
  std::string default_text;  // empty: no default (required, or derived by the entry)
  std::string meaning;
};

struct SpecInfo {
  std::string name, summary, source;
  std::vector<ParamInfo> params;
  // "name:key=default,...", KEY in capitals where there is no default.
  std::string usage() const;
};

// "name" and "key=value,..." of a spec's text, trimmed.
std::pair<std::string_view, std::string_view> split_spec(std::string_view text);

// A spec's parameters, checked against its entry: every key known, every
// value a finite number. Errors read "KIND NAME: ...".
class Spec {
 public:
  Spec(std::string kind, const SpecInfo& info, std::string_view parameters);

  const std::string& kind() const { return kind_; }
  const std::string& name() const { return info_->name; }
  bool given(std::string_view key) const { return values_.contains(key); }
  // The given value or the default; a parameter without either is an error
  // that asks for it.
  double number(std::string_view key) const;
  std::optional<double> optional_number(std::string_view key) const;
  // number(key), which must lie in [lo, hi] ((lo, hi] when open_lo).
  double in_range(std::string_view key, double lo, double hi, bool open_lo = false) const;
  // number(key), a whole number in lo..hi.
  int whole(std::string_view key, int lo, int hi) const;
  // "name:key=text,..." with every parameter that has a value, in the entry's order.
  std::string canonical() const;

 private:
  std::string kind_;
  const SpecInfo* info_;
  std::map<std::string, double, std::less<>> values_;
  std::map<std::string, std::string, std::less<>> texts_;
};

template <class T, class... Args>
class Registry {
 public:
  using Build = std::function<T(const Spec&, Args...)>;
  struct Entry {
    SpecInfo info;
    Build build;
  };

  Registry(std::string kind, std::vector<Entry> entries)
      : kind_(std::move(kind)), entries_(std::move(entries)) {}

  const std::string& kind() const { return kind_; }
  const std::vector<Entry>& entries() const { return entries_; }
  const Entry* find(std::string_view name) const {
    for (const Entry& e : entries_)
      if (e.info.name == name) return &e;
    return nullptr;
  }
  bool contains(std::string_view spec) const { return find(split_spec(spec).first) != nullptr; }
  // Parses `spec`, checks it against its entry and builds it.
  T make(std::string_view spec, Args... args) const {
    const auto [name, parameters] = split_spec(spec);
    const Entry* e = find(name);
    if (!e) unknown(name);
    return e->build(Spec(kind_, e->info, parameters), args...);
  }
  // Every name, comma separated, for messages.
  std::string names() const {
    std::string all;
    for (const Entry& e : entries_) all += (all.empty() ? "" : ", ") + e.info.name;
    return all;
  }
  [[noreturn]] void unknown(std::string_view name) const;

 private:
  std::string kind_;
  std::vector<Entry> entries_;
};

// "unknown KIND 'NAME': known KINDs are A, B, ..."
[[noreturn]] void throw_unknown_spec(std::string_view kind, std::string_view name,
                                     const std::string& known);

template <class T, class... Args>
void Registry<T, Args...>::unknown(std::string_view name) const {
  throw_unknown_spec(kind_, name, names());
}

}  // namespace aapat
