#include "aapat/generate/catalog.h"

#include <fmt/format.h>

#include <charconv>
#include <functional>
#include <sstream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"

namespace aapat {

namespace embedded {
extern const std::string_view kMsaaStandardPositionsCsv;
}

namespace {

using Builder = std::function<Pattern()>;

// Name, summary and the paper, table or figure it comes from.
struct CatalogText {
  std::string name, summary, source;
};

struct Entry {
  CatalogText info;
  Builder build;
};

std::vector<double> equal_weights(size_t n) {
  return std::vector<double>(n, 1.0 / n);
}

Pattern one_pixel(std::string name, std::vector<Vec2> s, std::vector<double> w = {},
                  Footprint f = {1, false}) {
  if (w.empty()) w = equal_weights(s.size());
  return single_pixel_pattern(std::move(name), std::move(s), std::move(w), f);
}

// Standard MSAA positions: sixteenths of a pixel from the centre, y down.
Pattern msaa_pattern(int count) {
  std::vector<Vec2> samples;
  std::istringstream in{std::string(embedded::kMsaaStandardPositionsCsv)};
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    int v[4] = {};
    const auto fields = split(line);
    for (size_t i = 0; i < 4 && i < fields.size(); ++i)
      std::from_chars(fields[i].data(), fields[i].data() + fields[i].size(), v[i]);
    if (v[0] == count) samples.push_back({v[2] / 16.0, -v[3] / 16.0});
  }
  return one_pixel(fmt::format("msaa-{}", count), samples);
}

// Cross's edge-optimized patterns (Goss & Wu Table 7): origin at the lower
// left corner of the pixel, so subtract the centre (0.5, 0.5).
Pattern cross_pattern(std::string name, const std::vector<Vec2>& corner_origin) {
  std::vector<Vec2> s;
  for (Vec2 p : corner_origin) s.push_back({p.x - 0.5, p.y - 0.5});
  return one_pixel(std::move(name), s);
}

Pattern hasselgren(std::string name, std::vector<Vec2> s, std::vector<double> w) {
  return mirrored_tile_pattern(std::move(name), std::move(s), std::move(w));
}

const std::vector<Entry>& entries() {
  static const std::vector<Entry> kEntries = {
      {{"centroid", "one sample at the pixel centre", "Hasselgren et al. 2005, Fig. 1a, Table 2"},
       [] {
         return one_pixel("centroid", {{0, 0}});
       }},
      {{"kyro-h", "two samples on the horizontal midline at x = -1/4, 1/4",
        "Hasselgren et al. 2005, Fig. 1b (positions read from the figure)"},
       [] {
         return one_pixel("kyro-h", {{-0.25, 0}, {0.25, 0}});
       }},
      {{"kyro-v", "two samples on the vertical midline at y = -1/4, 1/4",
        "Hasselgren et al. 2005, Fig. 1c (positions read from the figure)"},
       [] {
         return one_pixel("kyro-v", {{0, -0.25}, {0, 0.25}});
       }},
      {{"diagonal", "two samples at (-1/4, -1/4) and (1/4, 1/4)",
        "Hasselgren et al. 2005, Fig. 1d"},
       [] {
         return one_pixel("diagonal", {{-0.25, -0.25}, {0.25, 0.25}});
       }},
      {{"diagonal-hasselgren", "position-optimized diagonal, (+-0.259, +-0.339)",
        "Hasselgren et al. 2005, Table 2 'Diagonal' (E2 0.692; data/README.md)"},
       [] {
         return one_pixel("diagonal-hasselgren", {{-0.259, -0.339}, {0.259, 0.339}});
       }},
      {{"box2x2", "2x2 uniform grid at +-1/4", "Laine & Aila 2006, Table 2; Hasselgren Fig. 1e"},
       [] {
         return one_pixel("box2x2", {{-0.25, -0.25}, {0.25, -0.25}, {-0.25, 0.25}, {0.25, 0.25}});
       }},
      {{"rgss", "rotated grid: 4-rooks at +-1/8, +-3/8",
        "Laine & Aila 2006, Table 2; Hasselgren Fig. 1f"},
       [] {
         return one_pixel("rgss",
                          {{0.125, 0.375}, {0.375, -0.125}, {-0.125, -0.375}, {-0.375, 0.125}});
       }},
      {{"quincunx", "centre 1/2 and four shared corners 1/8 each",
        "Laine & Aila 2006, Table 2; Hasselgren Fig. 1g (NVIDIA HRAA)"},
       [] {
         return one_pixel("quincunx", {{0, 0}, {-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}},
                          {0.5, 0.125, 0.125, 0.125, 0.125}, {1, true});
       }},
      {{"quincunx-hasselgren", "weight-optimized Quincunx: centre 0.41, corners 0.1475",
        "Hasselgren et al. 2005, Table 2 'Quincunx' (E2 0.484; data/README.md)"},
       [] {
         return one_pixel("quincunx-hasselgren",
                          {{0, 0}, {-0.5, -0.5}, {0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}},
                          {0.41, 0.1475, 0.1475, 0.1475, 0.1475}, {1, true});
       }},
      {{"flipquad", "four edge samples 1/6 from the edge midpoints, mirrored 2x2 tile",
        "Akenine-Moller & Strom 2003; Laine & Aila 2006, Table 2"},
       [] {
         return hasselgren("flipquad",
                           {{-0.5, 1.0 / 6}, {0.5, -1.0 / 6}, {-1.0 / 6, -0.5}, {1.0 / 6, 0.5}},
                           equal_weights(4));
       }},
      {{"fliptri", "top-left corner and the bottom and right edge midpoints, weights 1/3",
        "Akenine-Moller 2003; Laine & Aila 2006, Table 2; Hasselgren Sec. 4"},
       [] {
         return hasselgren("fliptri", {{-0.5, 0.5}, {0, -0.5}, {0.5, 0}}, equal_weights(3));
       }},
      {{"hasselgren-a", "scheme A, optimized FLIPTRI, n = 1.25",
        "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-a", {{-0.5, 0.5}, {-0.133, -0.5}, {0.5, -0.064}},
                           {0.299, 0.360, 0.341});
       }},
      {{"hasselgren-b", "scheme B, n = 1.5", "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-b", {{-0.5, 0.073}, {-0.030, -0.5}, {0.313, 0.5}},
                           {0.335, 0.331, 0.334});
       }},
      {{"hasselgren-c", "scheme C, n = 1.5", "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-c", {{-0.5, 0.022}, {-0.5, -0.5}, {0.083, 0.5}, {0.5, -0.5}},
                           {0.306, 0.068, 0.338, 0.288});
       }},
      {{"hasselgren-d", "scheme D, n = 1.75", "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-d", {{-0.5, -0.5}, {-0.063, 0.318}, {0.5, -0.050}},
                           {0.280, 0.397, 0.323});
       }},
      {{"hasselgren-e", "scheme E, n = 1.75", "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-e",
                           {{-0.5, -0.5}, {-0.5, 0.045}, {0.004, 0.5}, {0.5, -0.222}},
                           {0.158, 0.156, 0.380, 0.306});
       }},
      {{"hasselgren-f", "scheme F, optimized FLIPQUAD, n = 2",
        "Hasselgren et al. 2005, Appendix A"},
       [] {
         return hasselgren("hasselgren-f",
                           {{-0.5, 0.143}, {0.5, -0.143}, {0.143, 0.5}, {-0.143, -0.5}},
                           equal_weights(4));
       }},
      {{"cross-4", "Cross's edge-optimized irregular grid, 4 samples",
        "Goss & Wu 2000, Table 7 'foursamples' (from Cross, Graphics Gems)"},
       [] {
         return cross_pattern("cross-4", {{0.274942, 0.884325},
                                          {0.797099, 0.207128},
                                          {0.765063, 0.715779},
                                          {0.122774, 0.282758}});
       }},
      {{"cross-16", "Cross's edge-optimized irregular grid, 16 samples",
        "Goss & Wu 2000, Table 7 'sixteensamples' (one sample lies on the top border)"},
       [] {
         return cross_pattern("cross-16", {{0.755279, 0.0497319},
                                           {0.384479, 0.688268},
                                           {0.666094, 0.868388},
                                           {0.317172, 0.0331764},
                                           {0.729309, 0.43103},
                                           {0.0867931, 0.368519},
                                           {0.322668, 1.0},
                                           {0.442302, 0.572752},
                                           {0.889074, 0.606985},
                                           {0.0343768, 0.191404},
                                           {0.910321, 0.872547},
                                           {0.92479, 0.345332},
                                           {0.289126, 0.389783},
                                           {0.896551, 0.141167},
                                           {0.23357, 0.678942},
                                           {0.11281, 0.526939}});
       }},
      {{"msaa-1", "standard MSAA, 1 sample", "Direct3D/Vulkan/Metal standard positions (data/)"},
       [] { return msaa_pattern(1); }},
      {{"msaa-2", "standard MSAA, 2 samples", "Direct3D/Vulkan/Metal standard positions (data/)"},
       [] { return msaa_pattern(2); }},
      {{"msaa-4", "standard MSAA, 4 samples", "Direct3D/Vulkan/Metal standard positions (data/)"},
       [] { return msaa_pattern(4); }},
      {{"msaa-8", "standard MSAA, 8 samples", "Direct3D/Vulkan/Metal standard positions (data/)"},
       [] { return msaa_pattern(8); }},
      {{"msaa-16", "standard MSAA, 16 samples", "Direct3D/Vulkan/Metal standard positions (data/)"},
       [] { return msaa_pattern(16); }},
      {{"grid-NxN", "uniform N x N grid, N = 1..32 (e.g. grid-4x4)", "regular supersampling"},
       nullptr},
  };
  return kEntries;
}

}  // namespace

const PatternRegistry& pattern_registry() {
  static const PatternRegistry kRegistry = [] {
    std::vector<PatternRegistry::Entry> list;
    for (const auto& e : entries()) {
      const SpecInfo info{e.info.name, e.info.summary, e.info.source, {}};
      if (!e.build) {  // grid-NxN: a template, built by catalog_pattern from its name
        list.push_back({info, [](const Spec&) -> Pattern {
                          throw Error("pattern grid-NxN: name the grid, e.g. grid-4x4");
                        }});
        continue;
      }
      list.push_back({info, [&e](const Spec&) {
                        Pattern p = e.build();
                        p.description = e.info.summary;
                        p.provenance = {{"catalog", e.info.name}, {"source", e.info.source}};
                        return p;
                      }});
    }
    return PatternRegistry("pattern", std::move(list));
  }();
  return kRegistry;
}

Pattern uniform_grid_pattern(int n) {
  std::vector<Vec2> s;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) s.push_back({(i + 0.5) / n - 0.5, (j + 0.5) / n - 0.5});
  return one_pixel(fmt::format("grid-{}x{}", n, n), s);
}

Pattern catalog_pattern(std::string_view name) {
  const PatternRegistry& registry = pattern_registry();
  if (registry.find(name) && name != "grid-NxN") return registry.make(name);
  if (name.starts_with("grid-")) {
    const std::string_view dims = name.substr(5);
    const auto x = dims.find('x');
    int a = 0, b = 0;
    const bool ok = x != std::string_view::npos &&
                    std::from_chars(dims.data(), dims.data() + x, a).ptr == dims.data() + x &&
                    std::from_chars(dims.data() + x + 1, dims.data() + dims.size(), b).ptr ==
                        dims.data() + dims.size();
    if (!ok || a != b || a < 1 || a > 32)
      throw Error(fmt::format("pattern '{}': a uniform grid is grid-NxN with N = 1..32", name));
    Pattern p = uniform_grid_pattern(a);
    p.description = fmt::format("uniform {}x{} grid", a, a);
    p.provenance = {{"catalog", "grid-NxN"}, {"source", "regular supersampling"}};
    return p;
  }
  throw Error(fmt::format("unknown pattern '{}': not a catalog name ({}) nor a .json file", name,
                          registry.names()));
}

}  // namespace aapat
