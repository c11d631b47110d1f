#include "aapat/io/api_export.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <sstream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/lattice.h"
#include "aapat/core/metric.h"
#include "aapat/core/text.h"

namespace aapat {
namespace {

constexpr std::string_view kExportMagic = "// aapat-export 1";

// A float literal every language reads: the shortest exact form, with a decimal point.
std::string float_literal(double v) {
  std::string t = fmt::format("{}", v);
  if (t.find_first_of(".e") == std::string::npos) t += ".0";
  return t;
}

std::string position_text(const ApiProfile& profile, LatticePoint q) {
  switch (profile.api) {
    case Api::kD3D12:
      return fmt::format("{{{}, {}}}", q.x - 8, q.y - 8);
    case Api::kVulkan:
      return fmt::format("{{{:.4f}f, {:.4f}f}}", q.x / 16.0, q.y / 16.0);
    case Api::kMetal:
      return fmt::format("MTLSamplePositionMake({:.4f}, {:.4f})", q.x / 16.0, q.y / 16.0);
    case Api::kOpenGL:
      return fmt::format("{:.4f}f, {:.4f}f", q.x / 16.0, q.y / 16.0);
  }
  return {};
}

std::string host_code(const HardwareLayout& L, const ApiProfile& profile) {
  const int pixels = L.grid_w * L.grid_h, total = pixels * L.sample_count;
  std::string out;
  auto array_open = [&](std::string_view type, std::string_view units, std::string_view call) {
    out += fmt::format("// Sample positions, {}.\n", units);
    out += fmt::format(
        "// Grid pixel (x, y), sample i: entry (y * {} + x) * {} + i; rows counted {}.\n", L.grid_w,
        L.sample_count, profile.y_down ? "from the top" : "from the bottom");
    out += fmt::format("// Use {}x MSAA. {}\n", L.sample_count, call);
    out += fmt::format("static const {} aapat_sample_positions[{}] = {{\n", type,
                       profile.api == Api::kOpenGL ? 2 * total : total);
  };
  switch (profile.api) {
    case Api::kD3D12:
      array_open("D3D12_SAMPLE_POSITION",
                 "in 1/16 pixel from the pixel centre, x right, y down, -8..7",
                 fmt::format("commandList->SetSamplePositions({}, {}, aapat_sample_positions);",
                             L.sample_count, pixels));
      break;
    case Api::kVulkan:
      array_open(
          "VkSampleLocationEXT",
          "from the pixel's upper-left corner, y down, in the guaranteed [0, 0.9375]",
          fmt::format("VkSampleLocationsInfoEXT: sampleLocationsPerPixel = "
                      "VK_SAMPLE_COUNT_{}_BIT, sampleLocationGridSize = {{{}, {}}}, "
                      "sampleLocationsCount = {}, pSampleLocations = aapat_sample_positions.",
                      L.sample_count, L.grid_w, L.grid_h, total));
      break;
    case Api::kMetal:
      array_open("MTLSamplePosition", "from the pixel's upper-left corner, y down, 0..15/16",
                 fmt::format("[renderPassDescriptor setSamplePositions:aapat_sample_positions "
                             "count:{}];",
                             total));
      break;
    case Api::kOpenGL:
      array_open("GLfloat", "(x, y) pairs from the pixel's lower-left corner, y up, 0..15/16",
                 fmt::format("glFramebufferSampleLocationsfvARB(GL_FRAMEBUFFER, 0, {}, "
                             "aapat_sample_positions); needs a {}x{} "
                             "SAMPLE_LOCATION_PIXEL_GRID and "
                             "FRAMEBUFFER_PROGRAMMABLE_SAMPLE_LOCATIONS_ARB.",
                             total, L.grid_w, L.grid_h));
      break;
  }
  for (int g = 0; g < pixels; ++g) {
    std::string row = "    ";
    for (int i = 0; i < L.sample_count; ++i) {
      row += position_text(profile, L.slot(g, i));
      if (g + 1 < pixels || i + 1 < L.sample_count) row += ", ";
    }
    out += fmt::format("{}  // pixel ({}, {}){}\n", row, g % L.grid_w, g / L.grid_w,
                       L.positions[g].size() < static_cast<size_t>(L.sample_count)
                           ? fmt::format(", {} own, the rest unused", L.positions[g].size())
                           : "");
  }
  out += "};\n";
  return out;
}

// The tap tables and the resolve loop in the shading language.
std::string shader_code(const HardwareLayout& L, const ApiProfile& profile, ShaderLanguage lang) {
  const int pixels = L.grid_w * L.grid_h;
  std::vector<int> start{0};
  std::string taps, weights;
  const char* int3 = lang == ShaderLanguage::kGlsl ? "ivec3" : "int3";
  for (int g = 0; g < pixels; ++g) {
    const auto& kernel = L.taps[g];
    start.push_back(start.back() + static_cast<int>(kernel.size()));
    std::string t_line, w_line;
    for (size_t i = 0; i < kernel.size(); ++i) {
      const bool last = g + 1 == pixels && i + 1 == kernel.size();
      t_line += fmt::format("{}({}, {}, {}){}", int3, kernel[i].dx, kernel[i].dy, kernel[i].sample,
                            last ? "" : ", ");
      w_line += fmt::format("{}{}", float_literal(kernel[i].weight), last ? "" : ", ");
    }
    const std::string where = fmt::format("  // pixel ({}, {})\n", g % L.grid_w, g / L.grid_w);
    taps += "    " + t_line + where;
    weights += "    " + w_line + where;
  }
  std::string starts;
  for (size_t i = 0; i < start.size(); ++i) starts += fmt::format("{}{}", i ? ", " : "", start[i]);
  const int n = start.back();
  const std::string grid_index =
      fmt::format("(p.y % {}) * {} + (p.x % {})", L.grid_h, L.grid_w, L.grid_w);
  const std::string about = fmt::format(
      "// Resolve: output pixel p (>= 0, rows {}) is the weighted sum of the samples its kernel\n"
      "// reads: tap t is sample taps[t].z of the pixel taps[t].xy away. {}\n",
      profile.y_down ? "from the top" : "from the bottom",
      L.footprint.size == 1
          ? "Edge pixels clamp."
          : "Even footprints reconstruct at the pixel's corner (+1/2, -1/2 in rows from the top): "
            "shift the image by half a pixel. Edge pixels clamp.");
  switch (lang) {
    case ShaderLanguage::kHlsl:
      return about + fmt::format(
                         "static const uint aapat_tap_start[{}] = {{{}}};\n"
                         "static const int3 aapat_taps[{}] = {{\n{}}};\n"
                         "static const float aapat_weights[{}] = {{\n{}}};\n\n"
                         "float4 aapat_resolve(Texture2DMS<float4> src, int2 p) {{\n"
                         "  uint w, h, count;\n"
                         "  src.GetDimensions(w, h, count);\n"
                         "  uint k = {};\n"
                         "  float4 c = 0;\n"
                         "  for (uint t = aapat_tap_start[k]; t < aapat_tap_start[k + 1]; ++t) {{\n"
                         "    int2 q = clamp(p + aapat_taps[t].xy, int2(0, 0), int2(w, h) - 1);\n"
                         "    c += aapat_weights[t] * src.Load(q, aapat_taps[t].z);\n"
                         "  }}\n"
                         "  return c;\n"
                         "}}\n",
                         pixels + 1, starts, n, taps, n, weights, grid_index);
    case ShaderLanguage::kGlsl:
      return about + fmt::format(
                         "const int aapat_tap_start[{}] = int[]({});\n"
                         "const ivec3 aapat_taps[{}] = ivec3[](\n{});\n"
                         "const float aapat_weights[{}] = float[](\n{});\n\n"
                         "vec4 aapat_resolve(sampler2DMS src, ivec2 p) {{\n"
                         "  ivec2 size = textureSize(src);\n"
                         "  int k = {};\n"
                         "  vec4 c = vec4(0.0);\n"
                         "  for (int t = aapat_tap_start[k]; t < aapat_tap_start[k + 1]; ++t) {{\n"
                         "    ivec2 q = clamp(p + aapat_taps[t].xy, ivec2(0), size - 1);\n"
                         "    c += aapat_weights[t] * texelFetch(src, q, aapat_taps[t].z);\n"
                         "  }}\n"
                         "  return c;\n"
                         "}}\n",
                         pixels + 1, starts, n, taps, n, weights, grid_index);
    case ShaderLanguage::kMsl:
      return about + fmt::format(
                         "constant uint aapat_tap_start[{}] = {{{}}};\n"
                         "constant int3 aapat_taps[{}] = {{\n{}}};\n"
                         "constant float aapat_weights[{}] = {{\n{}}};\n\n"
                         "float4 aapat_resolve(texture2d_ms<float> src, int2 p) {{\n"
                         "  int2 size = int2(src.get_width(), src.get_height());\n"
                         "  uint k = {};\n"
                         "  float4 c = 0;\n"
                         "  for (uint t = aapat_tap_start[k]; t < aapat_tap_start[k + 1]; ++t) {{\n"
                         "    int2 q = clamp(p + aapat_taps[t].xy, int2(0), size - 1);\n"
                         "    c += aapat_weights[t] * src.read(uint2(q), aapat_taps[t].z);\n"
                         "  }}\n"
                         "  return c;\n"
                         "}}\n",
                         pixels + 1, starts, n, taps, n, weights, grid_index);
  }
  return {};
}

[[noreturn]] void import_fail(std::string_view source, const std::string& message) {
  throw Error(fmt::format("import {}: {}", source, message));
}

// The numbers in the braces or parentheses that follow `name` (identifiers
// such as int3 or MTLSamplePositionMake are skipped whole).
std::vector<double> array_numbers(std::string_view text, std::string_view name,
                                  std::string_view source) {
  const auto at = text.find(std::string(name) + "[");
  if (at == std::string_view::npos) import_fail(source, fmt::format("no array '{}'", name));
  const auto eq = text.find('=', at);
  const auto end = text.find(';', eq);
  if (eq == std::string_view::npos || end == std::string_view::npos)
    import_fail(source, fmt::format("array '{}' is not terminated", name));
  return numbers_in(text.substr(eq + 1, end - eq - 1));
}

}  // namespace

std::vector<double> numbers_in(std::string_view code) {
  std::vector<double> values;
  size_t i = 0;
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < code.size()) {
    const char c = code[i];
    if (code.substr(i, 2) == "//") {
      i = code.find('\n', i);  // a comment, to the end of its line
      if (i == std::string_view::npos) break;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i < code.size() && ident(code[i])) ++i;  // int3, MTLSamplePositionMake, 0.5f's f
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
      size_t j = i + 1;
      while (j < code.size() &&
             (std::isalnum(static_cast<unsigned char>(code[j])) || code[j] == '.' ||
              ((code[j] == '-' || code[j] == '+') && (code[j - 1] == 'e' || code[j - 1] == 'E'))))
        ++j;
      std::string token(code.substr(i, j - i));
      if (!token.empty() && (token.back() == 'f' || token.back() == 'u')) token.pop_back();
      values.push_back(parse_number(token, "number"));
      i = j;
    } else {
      ++i;
    }
  }
  return values;
}

namespace {

int whole(double v, std::string_view source, std::string_view what) {
  if (v != std::floor(v) || std::abs(v) > 1e6)
    import_fail(source, fmt::format("{}: {} is not a whole number", what, v));
  return static_cast<int>(v);
}

}  // namespace

ShaderLanguage default_shader(const ApiProfile& profile) {
  return profile.api == Api::kD3D12   ? ShaderLanguage::kHlsl
         : profile.api == Api::kMetal ? ShaderLanguage::kMsl
                                      : ShaderLanguage::kGlsl;
}

ShaderLanguage parse_shader_language(std::string_view name) {
  if (name == "hlsl") return ShaderLanguage::kHlsl;
  if (name == "glsl") return ShaderLanguage::kGlsl;
  if (name == "msl") return ShaderLanguage::kMsl;
  throw Error(fmt::format("unknown shader language '{}': expected hlsl, glsl or msl", name));
}

std::string export_layout(const HardwareLayout& L, ShaderLanguage shader,
                          const std::vector<std::string>& notes) {
  const ApiProfile& profile = api_profile(L.profile);
  std::string out = fmt::format("{} profile={} grid={}x{} samples={} footprint={} name={}\n",
                                kExportMagic, L.profile, L.grid_w, L.grid_h, L.sample_count,
                                L.footprint.text(), one_line(L.name));
  out += fmt::format("// {}: {}\n", profile.name, profile.summary);
  for (const auto& n : notes) out += fmt::format("// {}\n", one_line(n));
  out += fmt::format("\n{}\n{}", host_code(L, profile), shader_code(L, profile, shader));
  return out;
}

HardwareLayout parse_export(std::string_view text, std::string_view source) {
  const auto eol = text.find('\n');
  const std::string_view head = text.substr(0, eol);
  if (!head.starts_with(kExportMagic))
    import_fail(source, fmt::format("the first line is not '{} ...' (written by aapat export)",
                                    kExportMagic));
  HardwareLayout L;
  std::istringstream fields{std::string(head.substr(kExportMagic.size()))};
  std::string field;
  bool grid = false, samples = false, footprint = false;
  while (fields >> field) {
    const auto eq = field.find('=');
    const std::string key = field.substr(0, eq), value = field.substr(eq + 1);
    if (key == "profile") {
      L.profile = api_profile(value).name;
    } else if (key == "grid") {
      const auto x = value.find('x');
      L.grid_w = whole(parse_number(value.substr(0, x), "grid"), source, "grid");
      L.grid_h = whole(parse_number(value.substr(x + 1), "grid"), source, "grid");
      grid = true;
    } else if (key == "samples") {
      L.sample_count = whole(parse_number(value, "samples"), source, "samples");
      samples = true;
    } else if (key == "footprint") {
      L.footprint = parse_footprint(value);
      footprint = true;
    } else if (key == "name") {
      L.name = value;
    }
  }
  if (L.profile.empty() || !grid || !samples || !footprint)
    import_fail(source, "the first line needs profile=, grid=, samples= and footprint=");
  const ApiProfile& profile = api_profile(L.profile);
  if (L.grid_w < 1 || L.grid_h < 1 || L.grid_w > profile.max_grid || L.grid_h > profile.max_grid ||
      L.sample_count < 1 || L.sample_count > 16)
    import_fail(source, fmt::format("grid {}x{} with {} samples is outside what {} allows",
                                    L.grid_w, L.grid_h, L.sample_count, profile.name));
  const int pixels = L.grid_w * L.grid_h;
  const auto pos = array_numbers(text, "aapat_sample_positions", source);
  if (pos.size() != static_cast<size_t>(2 * pixels * L.sample_count))
    import_fail(source, fmt::format("aapat_sample_positions holds {} numbers, expected {}",
                                    pos.size(), 2 * pixels * L.sample_count));
  L.positions.resize(pixels);
  for (size_t i = 0; i < pos.size(); i += 2) {
    const double scale = profile.api == Api::kD3D12 ? 1 : 16,
                 shift = profile.api == Api::kD3D12 ? 8 : 0;
    const double x = pos[i] * scale + shift, y = pos[i + 1] * scale + shift;
    if (x != std::floor(x) || y != std::floor(y) || x < 0 || x > 15 || y < 0 || y > 15)
      import_fail(source, fmt::format("sample position ({}, {}) is not a legal {} lattice position",
                                      pos[i], pos[i + 1], profile.name));
    L.positions[i / 2 / L.sample_count].push_back({static_cast<int>(x), static_cast<int>(y)});
  }
  const auto start = array_numbers(text, "aapat_tap_start", source);
  const auto taps = array_numbers(text, "aapat_taps", source);
  const auto weights = array_numbers(text, "aapat_weights", source);
  if (start.size() != static_cast<size_t>(pixels + 1) || taps.size() != 3 * weights.size() ||
      start.back() != static_cast<double>(weights.size()) || start.front() != 0)
    import_fail(source, "the tap tables do not agree in size with each other and the grid");
  L.taps.resize(pixels);
  for (int g = 0; g < pixels; ++g) {
    const int a = whole(start[g], source, "aapat_tap_start"),
              b = whole(start[g + 1], source, "aapat_tap_start");
    if (a > b) import_fail(source, "aapat_tap_start is not increasing");
    for (int t = a; t < b; ++t)
      L.taps[g].push_back({whole(taps[3 * t], source, "aapat_taps"),
                           whole(taps[3 * t + 1], source, "aapat_taps"),
                           whole(taps[3 * t + 2], source, "aapat_taps"), weights[t]});
  }
  return L;
}

void check_export_grid(const ApiProfile& profile, int grid_w, int grid_h, std::string_view what) {
  if (!profile.grid_choice) throw Error(fmt::format("{}: {} has a fixed grid", what, profile.name));
  if (grid_w < 1 || grid_h < 1 || grid_w > profile.max_grid || grid_h > profile.max_grid)
    throw Error(fmt::format("{}: {}x{}; {} takes 1 to {} a side", what, grid_w, grid_h,
                            profile.name, profile.max_grid));
}

std::string export_pattern(const Pattern& pattern, const ApiProfile& profile,
                           const Objective& objective, ShaderLanguage shader, bool snap, int grid_w,
                           int grid_h) {
  const Metric metric = objective.metric();
  const Pattern p = snap ? snap_to_lattice(pattern, kLatticeSteps) : pattern;
  const HardwareLayout L = hardware_layout(p, profile, grid_w, grid_h);
  std::vector<std::string> notes{
      fmt::format("{} {}: E2 {:.4f} under the {}{}", p.name, family(p), metric.evaluate(p).e2,
                  objective.caption(),
                  snap ? fmt::format(", snapped from E2 {:.4f}", metric.evaluate(pattern).e2) : ""),
      fmt::format("{} samples per pixel; the resolve reads {} per output pixel",
                  format_cost(samples_per_pixel(p)), format_cost(L.reads()))};
  // What it was designed for, from its provenance, beside the E2 under it.
  if (const auto designed = design_objective(pattern); designed && *designed != objective)
    notes.insert(notes.begin() + 1,
                 fmt::format("designed for the {}: E2 {:.4f} under it", designed->caption(),
                             designed->metric().evaluate(p).e2));
  else if (designed)
    notes.insert(notes.begin() + 1, "designed for this objective");
  return export_layout(L, shader, notes);
}

}  // namespace aapat
