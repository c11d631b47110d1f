#include "aapat/core/spec.h"

#include "aapat/core/nearest_name.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/geometry.h"
#include "aapat/core/text.h"

namespace aapat {

std::string SpecInfo::usage() const {
  std::string text = name;
  bool first = true;
  for (const ParamInfo& p : params) {
    std::string value = p.default_text;  // or a placeholder: "step=STEP"
    if (value.empty())
      for (char c : p.key) value += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    text += fmt::format("{}{}={}", first ? ":" : ",", p.key, value);
    first = false;
  }
  return text;
}

std::pair<std::string_view, std::string_view> split_spec(std::string_view text) {
  text = trim(text);
  const auto colon = text.find(':');
  if (colon == std::string_view::npos) return {text, {}};
  return {trim(text.substr(0, colon)), trim(text.substr(colon + 1))};
}

void throw_unknown_spec(std::string_view kind, std::string_view name, const std::string& known) {
  std::vector<std::string> names;
  for (std::string_view n : split(known)) names.emplace_back(trim(n));
  throw Error(fmt::format("unknown {} '{}'{}: known {}s are {}", kind, name,
                          did_you_mean(name, names), kind, known));
}

Spec::Spec(std::string kind, const SpecInfo& info, std::string_view parameters)
    : kind_(std::move(kind)), info_(&info) {
  for (const ParamInfo& p : info.params)
    if (!p.default_text.empty()) {
      values_[p.key] = parse_number(p.default_text, fmt::format("{} {}: {}", kind_, name(), p.key));
      texts_[p.key] = p.default_text;
    }
  if (parameters.empty()) return;
  for (std::string_view item : split(parameters)) {
    item = trim(item);
    const auto eq = item.find('=');
    const std::string_view key = trim(item.substr(0, eq));
    const bool known = std::any_of(info.params.begin(), info.params.end(),
                                   [&](const ParamInfo& p) { return p.key == key; });
    if (eq == std::string_view::npos || !known) {
      std::string takes;
      for (const ParamInfo& p : info.params) takes += (takes.empty() ? "" : ", ") + p.key;
      throw Error(fmt::format("{} {}: unknown parameter '{}' ({})", kind_, name(), item,
                              takes.empty() ? "it takes no parameters" : "it takes " + takes));
    }
    const std::string_view text = trim(item.substr(eq + 1));
    values_[std::string(key)] = parse_number(text, fmt::format("{} {}: {}", kind_, name(), key));
    texts_[std::string(key)] = std::string(text);
  }
}

std::optional<double> Spec::optional_number(std::string_view key) const {
  const auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

double Spec::number(std::string_view key) const {
  if (const auto v = optional_number(key)) return *v;
  std::string meaning;
  for (const ParamInfo& p : info_->params)
    if (p.key == key) meaning = p.meaning;
  throw Error(
      fmt::format("{} {}: give {} ({}), e.g. {}:{}=1", kind_, name(), key, meaning, name(), key));
}

double Spec::in_range(std::string_view key, double lo, double hi, bool open_lo) const {
  const double v = number(key);
  if (!(open_lo ? v > lo : v >= lo) || !(v <= hi))
    throw Error(fmt::format("{} {}: {} = {} is out of range {}{}, {}]", kind_, name(), key, v,
                            open_lo ? "(" : "[", lo, hi));
  return v;
}

int Spec::whole(std::string_view key, int lo, int hi) const {
  const double v = number(key);
  if (v != std::floor(v) || v < lo || v > hi)
    throw Error(fmt::format("{} {}: {} = {} must be a whole number in {}..{}", kind_, name(), key,
                            v, lo, hi));
  return static_cast<int>(v);
}

std::string Spec::canonical() const {
  std::string text = name();
  bool first = true;
  for (const ParamInfo& p : info_->params) {
    const auto it = texts_.find(p.key);
    if (it == texts_.end()) continue;
    text += fmt::format("{}{}={}", first ? ":" : ",", p.key, it->second);
    first = false;
  }
  return text;
}

}  // namespace aapat
