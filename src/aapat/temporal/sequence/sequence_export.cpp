#include "aapat/temporal/sequence/sequence_export.h"

#include <fmt/format.h>

#include "aapat/core/lattice.h"
#include "aapat/core/text.h"
#include "aapat/io/api_export.h"

namespace aapat {
namespace {

bool is_jitter(const Sequence& s) {
  for (const Pattern& p : s.frames)
    if (p.set_count() != 1 || p.sets[0].size() != 1) return false;
  return true;
}

}  // namespace

ExportLanguage parse_export_language(std::string_view name) {
  if (name == "hlsl") return ExportLanguage::hlsl;
  if (name == "glsl") return ExportLanguage::glsl;
  if (name == "c++" || name == "cpp") return ExportLanguage::cpp;
  throw ParameterError("language", fmt::format(" '{}': expected hlsl, glsl or c++", name));
}

std::string export_jitter(const Sequence& s, ExportLanguage language, bool y_down) {
  validate(s);
  if (!is_jitter(s))
    throw Error(
        fmt::format("sequence {}: its frames take several samples (or tiles); export it "
                    "for an API profile (--api) instead of as a jitter array",
                    s.name));
  const int k = s.period();
  std::string out = fmt::format(
      "// aapat sequence {}: {} jitter offsets in pixels from the pixel centre, +x right, +y {}.\n"
      "// Frame f uses offset f mod {}.\n",
      one_line(s.name), k, y_down ? "down (screen rows)" : "up", k);
  for (const auto& [key, value] : s.provenance)
    out += fmt::format("// {}: {}\n", one_line(key), one_line(value));
  auto pair = [&](const Pattern& p, const char* open, const char* close) {
    const Vec2 v = p.sets[0][0];
    return fmt::format("{}{:.17g}, {:.17g}{}", open, v.x, y_down ? -v.y : v.y, close);
  };
  std::string items;
  for (int f = 0; f < k; ++f) {
    const Pattern& p = s.frames[static_cast<size_t>(f)];
    if (f) items += ",\n";
    switch (language) {
      case ExportLanguage::hlsl:
        items += pair(p, "    float2(", ")");
        break;
      case ExportLanguage::glsl:
        items += pair(p, "    vec2(", ")");
        break;
      case ExportLanguage::cpp:
        items += pair(p, "    {", "}");
        break;
    }
  }
  switch (language) {
    case ExportLanguage::hlsl:
      return out + fmt::format(
                       "static const uint kJitterCount = {};\nstatic const float2 "
                       "kJitter[{}] = {{\n{}\n}};\n",
                       k, k, items);
    case ExportLanguage::glsl:
      return out + fmt::format(
                       "const int kJitterCount = {};\nconst vec2 kJitter[{}] = vec2[{}](\n{}\n);\n",
                       k, k, k, items);
    case ExportLanguage::cpp:
      return out + fmt::format(
                       "inline constexpr int kJitterCount = {};\ninline constexpr double "
                       "kJitter[{}][2] = {{\n{}\n}};\n",
                       k, k, items);
  }
  return out;
}

std::string export_msaa_sequence(const Sequence& s, const ApiProfile& profile) {
  validate(s);
  std::string out =
      fmt::format("// aapat sequence {}: {} frames for {}, frame f uses block f mod {}.\n",
                  one_line(s.name), s.period(), profile.name, s.period());
  for (int f = 0; f < s.period(); ++f) {
    const Pattern snapped =
        snap_to_lattice(s.frames[static_cast<size_t>(f)], kLatticeSteps, profile.y_down);
    try {
      const HardwareLayout layout = hardware_layout(snapped, profile);
      out += fmt::format("\n// ---- frame {} ----\n", f);
      out += export_layout(layout, default_shader(profile),
                           {fmt::format("frame {} of {}", f, s.period())});
    } catch (const Error& e) {
      throw Error(fmt::format("sequence {}: frame {}: {}", s.name, f, e.what()));
    }
  }
  return out;
}

}  // namespace aapat
