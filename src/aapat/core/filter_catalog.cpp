#include "aapat/core/filter_catalog.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>

#include "aapat/core/geometry.h"
#include "aapat/core/text.h"

namespace aapat {
const FilterRegistry& filter_registry() {
  static const FilterRegistry kRegistry(
      "filter",
      {
          {{"box",
            "rectangle of the given width (Goss-Wu 'box', the A-buffer's filter)",
            "Goss & Wu 2000, Table 3 (rectangle)",
            {{"width", "1", "support width in pixels"}}},
           [](const Spec& s) { return BoxShape{s.in_range("width", 1e-3, 16)}; }},
          {{"tent",
            "triangle 1 - |x|/radius",
            "Goss & Wu 2000, Table 3 (triangle) and Sec. 3.3.2",
            {{"radius", "1", "half width in pixels"}}},
           [](const Spec& s) { return TentShape{s.in_range("radius", 1e-3, 16)}; }},
          {{"gaussian",
            "exp(-x^2 / (2 sigma^2)), truncated at the radius (not shifted)",
            "defaults as pbrt-v4's Gaussian filter",
            {{"sigma", "0.5", "standard deviation in pixels"},
             {"radius", "1.5", "truncation radius"}}},
           [](const Spec& s) {
             return GaussianShape{s.in_range("sigma", 1e-3, 16), s.in_range("radius", 1e-3, 16)};
           }},
          {{"gaussian-half",
            "Goss-Wu 'Gaussian 1/2': 2^(-4x^2), height 1/2 at 1/2, cut at 1.5",
            "Goss & Wu 2000, Sec. 3.3.3 (sigma = 1/sqrt(8 ln 2) = 0.4247)",
            {}},
           [](const Spec&) {
             return GaussianShape{1.0 / std::sqrt(8.0 * std::log(2.0)), 1.5};
           }},
          {{"mitchell",
            "Mitchell-Netravali cubic (B, C), radius 2",
            "Mitchell & Netravali 1988; (1/3, 1/3) is the reference of Laine-Aila and Hasselgren",
            {{"b", "1/3", "B parameter"}, {"c", "1/3", "C parameter"}}},
           [](const Spec& s) {
             return MitchellShape{s.in_range("b", -10, 10), s.in_range("c", -10, 10)};
           }},
          {{"notch",
            "Mitchell-Netravali notch filter (B, C) = (3/2, -1/4)",
            "Mitchell & Netravali 1988 (cited by Laine-Aila Sec. 2)",
            {}},
           [](const Spec&) {
             return MitchellShape{1.5, -0.25};
           }},
          {{"catmull-rom",
            "Catmull-Rom spline, Mitchell-Netravali (B, C) = (0, 1/2)",
            "Mitchell & Netravali 1988; Keys' cubic with a = -1/2",
            {}},
           [](const Spec&) {
             return MitchellShape{0.0, 0.5};
           }},
          {{"keys",
            "Keys' cubic convolution with parameter a (= Mitchell-Netravali B = 0, C = -a)",
            "Goss & Wu 2000, Table 3 (cubic)",
            {{"a", "-1/2", "Keys' a"}}},
           [](const Spec& s) {
             return MitchellShape{0.0, -s.in_range("a", -10, 10)};
           }},
          {{"lanczos",
            "Lanczos-M windowed sinc: sinc(x) sinc(x/M) on |x| < M",
            "Goss & Wu 2000, Table 3 (Lanczos-M sinc)",
            {{"lobes", "3", "M, the radius in pixels"}}},
           [](const Spec& s) { return LanczosShape{s.whole("lobes", 1, 16)}; }},
          {{"lanczos-gaussian",
            "Lanczos-windowed Gaussian: exp(-x^2/(2 sigma^2)) sinc(x/M), |x| < M",
            "Goss & Wu 2000, Table 3 (Lanczos-M Gaussian; sigma is a parameter here)",
            {{"lobes", "2", "M, the radius in pixels"}, {"sigma", "0.5", "Gaussian deviation"}}},
           [](const Spec& s) {
             return LanczosGaussianShape{s.whole("lobes", 1, 16), s.in_range("sigma", 1e-3, 16)};
           }},
          {{"blinn",
            "Blinn's nice filter: sinc(x/2) sinc(x/4) on |x| < 4",
            "Goss & Wu 2000, Table 3 and Table 4 (8N x 8N kernel); see docs/filters.md",
            {}},
           [](const Spec&) { return BlinnNiceShape{}; }},
      });
  return kRegistry;
}

namespace {

// The whole text as a decimal number, as std::from_chars reads it: no leading
// '+', no hexadecimal, nothing after it.
bool read_decimal(std::string_view text, double& v) {
#if defined(__EMSCRIPTEN__)
  // The WebAssembly build's libc++ has no floating-point from_chars; strtod
  // (always the "C" locale there) reads the same texts once the characters
  // from_chars would refuse are refused first.
  if (text.empty() || text.front() == '+' ||
      text.find_first_not_of("0123456789.eE+-") != std::string_view::npos)
    return false;
  const std::string copy(text);
  char* end = nullptr;
  v = std::strtod(copy.c_str(), &end);
  return end == copy.c_str() + copy.size();
#else
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return ec == std::errc() && ptr == text.data() + text.size();
#endif
}

double parse_plain(std::string_view text, std::string_view what, std::string_view whole_text) {
  double v = 0;
  if (!read_decimal(text, v) || !std::isfinite(v))
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
  if (x == std::string_view::npos && text.find_first_not_of("0123456789") != std::string_view::npos)
    throw Error(fmt::format("{}: '{}' is not WIDTHxHEIGHT nor N (N x N)", what, text));
  const double w = parse_number(text.substr(0, x), what),
               h = x == std::string_view::npos ? w : parse_number(text.substr(x + 1), what);
  if (!(w >= 1 && h >= 1 && w <= max && h <= max) || w != std::floor(w) || h != std::floor(h))
    throw Error(fmt::format("{}: '{}' must be whole numbers from 1 to {}", what, text, max));
  return {static_cast<int>(w), static_cast<int>(h)};
}

Filter make_filter(std::string_view text) {
  const FilterRegistry& registry = filter_registry();
  const auto [name, parameters] = split_spec(text);
  const FilterRegistry::Entry* entry = registry.find(name);
  if (!entry) registry.unknown(name);
  const Spec spec(registry.kind(), entry->info, parameters);
  return Filter(entry->build(spec), spec.canonical());
}

}  // namespace aapat
