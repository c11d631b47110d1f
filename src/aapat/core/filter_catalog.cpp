#include "aapat/core/filter_catalog.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <functional>
#include <map>

#include "aapat/core/geometry.h"
#include "aapat/core/text.h"

namespace aapat {
namespace {

using Params = std::map<std::string, double, std::less<>>;

struct FilterEntry {
  FilterInfo info;
  std::function<FilterShape(const Params&)> build;
};

double in_range(const Params& p, const std::string& key, double lo, double hi, bool open_lo,
                std::string_view filter) {
  const double v = p.at(key);
  if (!(open_lo ? v > lo : v >= lo) || !(v <= hi))
    throw Error(fmt::format("filter {}: {} = {} is out of range {}{}, {}]", filter, key, v,
                            open_lo ? "(" : "[", lo, hi));
  return v;
}

int whole(const Params& p, const std::string& key, int lo, int hi, std::string_view filter) {
  const double v = p.at(key);
  if (v != std::floor(v) || v < lo || v > hi)
    throw Error(
        fmt::format("filter {}: {} = {} must be a whole number in {}..{}", filter, key, v, lo, hi));
  return static_cast<int>(v);
}

const std::vector<FilterEntry>& entries() {
  static const std::vector<FilterEntry> kEntries = {
      {{"box",
        "rectangle of the given width (Goss-Wu 'box', the A-buffer's filter)",
        "Goss & Wu 2000, Table 3 (rectangle)",
        {{"width", "1", "support width in pixels"}}},
       [](const Params& p) { return BoxShape{in_range(p, "width", 1e-3, 16, false, "box")}; }},
      {{"tent",
        "triangle 1 - |x|/radius",
        "Goss & Wu 2000, Table 3 (triangle) and Sec. 3.3.2",
        {{"radius", "1", "half width in pixels"}}},
       [](const Params& p) { return TentShape{in_range(p, "radius", 1e-3, 16, false, "tent")}; }},
      {{"gaussian",
        "exp(-x^2 / (2 sigma^2)), truncated at the radius (not shifted)",
        "defaults as pbrt-v4's Gaussian filter",
        {{"sigma", "0.5", "standard deviation in pixels"}, {"radius", "1.5", "truncation radius"}}},
       [](const Params& p) {
         return GaussianShape{in_range(p, "sigma", 1e-3, 16, false, "gaussian"),
                              in_range(p, "radius", 1e-3, 16, false, "gaussian")};
       }},
      {{"gaussian-half",
        "Goss-Wu 'Gaussian 1/2': 2^(-4x^2), height 1/2 at 1/2, cut at 1.5",
        "Goss & Wu 2000, Sec. 3.3.3 (sigma = 1/sqrt(8 ln 2) = 0.4247)",
        {}},
       [](const Params&) {
         return GaussianShape{1.0 / std::sqrt(8.0 * std::log(2.0)), 1.5};
       }},
      {{"mitchell",
        "Mitchell-Netravali cubic (B, C), radius 2",
        "Mitchell & Netravali 1988; (1/3, 1/3) is the reference of Laine-Aila and Hasselgren",
        {{"b", "1/3", "B parameter"}, {"c", "1/3", "C parameter"}}},
       [](const Params& p) {
         return MitchellShape{in_range(p, "b", -10, 10, false, "mitchell"),
                              in_range(p, "c", -10, 10, false, "mitchell")};
       }},
      {{"notch",
        "Mitchell-Netravali notch filter (B, C) = (3/2, -1/4)",
        "Mitchell & Netravali 1988 (cited by Laine-Aila Sec. 2)",
        {}},
       [](const Params&) {
         return MitchellShape{1.5, -0.25};
       }},
      {{"catmull-rom",
        "Catmull-Rom spline, Mitchell-Netravali (B, C) = (0, 1/2)",
        "Mitchell & Netravali 1988; Keys' cubic with a = -1/2",
        {}},
       [](const Params&) {
         return MitchellShape{0.0, 0.5};
       }},
      {{"keys",
        "Keys' cubic convolution with parameter a (= Mitchell-Netravali B = 0, C = -a)",
        "Goss & Wu 2000, Table 3 (cubic)",
        {{"a", "-1/2", "Keys' a"}}},
       [](const Params& p) {
         return MitchellShape{0.0, -in_range(p, "a", -10, 10, false, "keys")};
       }},
      {{"lanczos",
        "Lanczos-M windowed sinc: sinc(x) sinc(x/M) on |x| < M",
        "Goss & Wu 2000, Table 3 (Lanczos-M sinc)",
        {{"lobes", "3", "M, the radius in pixels"}}},
       [](const Params& p) { return LanczosShape{whole(p, "lobes", 1, 16, "lanczos")}; }},
      {{"lanczos-gaussian",
        "Lanczos-windowed Gaussian: exp(-x^2/(2 sigma^2)) sinc(x/M), |x| < M",
        "Goss & Wu 2000, Table 3 (Lanczos-M Gaussian; sigma is a parameter here)",
        {{"lobes", "2", "M, the radius in pixels"}, {"sigma", "0.5", "Gaussian deviation"}}},
       [](const Params& p) {
         return LanczosGaussianShape{whole(p, "lobes", 1, 16, "lanczos-gaussian"),
                                     in_range(p, "sigma", 1e-3, 16, false, "lanczos-gaussian")};
       }},
      {{"blinn",
        "Blinn's nice filter: sinc(x/2) sinc(x/4) on |x| < 4",
        "Goss & Wu 2000, Table 3 and Table 4 (8N x 8N kernel); see docs/filters.md",
        {}},
       [](const Params&) { return BlinnNiceShape{}; }},
  };
  return kEntries;
}

double parse_plain(std::string_view text, std::string_view what, std::string_view whole_text) {
  double v = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
    throw Error(fmt::format("{}: '{}' is not a finite number", what, whole_text));
  return v;
}

}  // namespace

double parse_number(std::string_view text, std::string_view what) {
  text = trim(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return parse_plain(text, what, text);
  const double num = parse_plain(trim(text.substr(0, slash)), what, text);
  const double den = parse_plain(trim(text.substr(slash + 1)), what, text);
  if (den == 0) throw Error(fmt::format("{}: '{}' divides by zero", what, text));
  return num / den;
}

std::pair<int, int> parse_size(std::string_view text, std::string_view what, int max) {
  const auto x = text.find('x');
  if (x == std::string_view::npos)
    throw Error(fmt::format("{}: '{}' is not WIDTHxHEIGHT", what, text));
  const double w = parse_number(text.substr(0, x), what),
               h = parse_number(text.substr(x + 1), what);
  if (!(w >= 1 && h >= 1 && w <= max && h <= max) || w != std::floor(w) || h != std::floor(h))
    throw Error(fmt::format("{}: '{}' must be whole numbers from 1 to {}", what, text, max));
  return {static_cast<int>(w), static_cast<int>(h)};
}

const std::vector<FilterInfo>& filter_catalog() {
  static const std::vector<FilterInfo> kInfos = [] {
    std::vector<FilterInfo> v;
    for (const auto& e : entries()) v.push_back(e.info);
    return v;
  }();
  return kInfos;
}

Filter make_filter(std::string_view spec) {
  spec = trim(spec);
  const auto colon = spec.find(':');
  const std::string_view name = trim(spec.substr(0, colon));
  const FilterEntry* entry = nullptr;
  for (const auto& e : entries())
    if (e.info.name == name) entry = &e;
  if (!entry) {
    std::string known;
    for (const auto& e : entries()) known += (known.empty() ? "" : ", ") + e.info.name;
    throw Error(fmt::format("unknown filter '{}': known filters are {}", name, known));
  }
  Params values;
  std::map<std::string, std::string, std::less<>> texts;
  for (const auto& p : entry->info.params) {
    texts[p.key] = p.default_text;
    values[p.key] = parse_number(p.default_text, p.key);
  }
  if (colon != std::string_view::npos) {
    for (std::string_view item : split(spec.substr(colon + 1))) {
      item = trim(item);
      const auto eq = item.find('=');
      const std::string_view key = trim(item.substr(0, eq));
      if (eq == std::string_view::npos || !texts.contains(key)) {
        std::string takes;
        for (const auto& p : entry->info.params) takes += (takes.empty() ? "" : ", ") + p.key;
        throw Error(fmt::format("filter {}: unknown parameter '{}' ({})", name, item,
                                takes.empty() ? "it takes no parameters" : "it takes " + takes));
      }
      const std::string_view value_text = trim(item.substr(eq + 1));
      values[std::string(key)] = parse_number(value_text, fmt::format("filter {}: {}", name, key));
      texts[std::string(key)] = std::string(value_text);
    }
  }
  std::string canonical(name);
  for (size_t i = 0; i < entry->info.params.size(); ++i) {
    const auto& key = entry->info.params[i].key;
    canonical += fmt::format("{}{}={}", i == 0 ? ":" : ",", key, texts[key]);
  }
  return Filter(entry->build(values), canonical);
}

}  // namespace aapat
