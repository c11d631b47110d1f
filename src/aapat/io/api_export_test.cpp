#include "aapat/io/api_export.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/core/objective.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/pattern_json.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

std::string golden_path(const std::string& name) {
  return std::string(AAPAT_TESTDATA_DIR) + "/golden/" + name;
}

// Compares with the committed file; AAPAT_UPDATE_GOLDEN=1 rewrites it instead.
void expect_golden(const std::string& name, const std::string& text) {
  if (std::getenv("AAPAT_UPDATE_GOLDEN")) {
    write_file_atomically(golden_path(name), text);
    return;
  }
  EXPECT_EQ(text, read_file(golden_path(name), "golden file")) << name;
}

struct Case {
  const char* file;
  const char* pattern;
  const char* profile;
  int grid;
  ShaderLanguage shader;
};

const Case kCases[] = {
    {"flipquad-d3d12-tier2.hlsl.txt", "flipquad", "d3d12-tier2", 0, ShaderLanguage::kHlsl},
    {"flipquad-vulkan.glsl.txt", "flipquad", "vulkan", 2, ShaderLanguage::kGlsl},
    {"flipquad-gl.glsl.txt", "flipquad", "gl", 0, ShaderLanguage::kGlsl},
    {"quincunx-d3d12-tier1.hlsl.txt", "quincunx", "d3d12-tier1", 0, ShaderLanguage::kHlsl},
    {"rgss-metal.msl.txt", "rgss", "metal", 0, ShaderLanguage::kMsl},
    {"hasselgren-a-vulkan.glsl.txt", "hasselgren-a", "vulkan", 0, ShaderLanguage::kGlsl},
};

HardwareLayout layout_of(const Case& c) {
  return hardware_layout(snap_to_lattice(catalog_pattern(c.pattern), 16), api_profile(c.profile),
                         c.grid, c.grid);
}

TEST(ApiExport, GoldenFilesAndRoundTrips) {
  for (const Case& c : kCases) {
    const HardwareLayout L = layout_of(c);
    const std::string text = export_layout(L, c.shader, {"a note"});
    expect_golden(c.file, text);
    const HardwareLayout back = parse_export(text, c.file);
    EXPECT_EQ(back.profile, L.profile);
    EXPECT_EQ(back.grid_w, L.grid_w);
    EXPECT_EQ(back.sample_count, L.sample_count);
    ASSERT_EQ(back.taps.size(), L.taps.size());
    for (size_t g = 0; g < L.taps.size(); ++g) {
      // Padding repeats a pixel's first sample: the owned ones come first.
      for (size_t i = 0; i < L.positions[g].size(); ++i)
        EXPECT_EQ(back.positions[g][i], L.positions[g][i]) << c.file;
      ASSERT_EQ(back.taps[g].size(), L.taps[g].size());
      for (size_t t = 0; t < L.taps[g].size(); ++t) {
        EXPECT_EQ(back.taps[g][t].dx, L.taps[g][t].dx);
        EXPECT_EQ(back.taps[g][t].dy, L.taps[g][t].dy);
        EXPECT_EQ(back.taps[g][t].sample, L.taps[g][t].sample);
        EXPECT_EQ(back.taps[g][t].weight, L.taps[g][t].weight);  // exact: shortest round-trip text
      }
    }
    if (L.footprint.size == 1) {
      const Pattern p = pattern_from_layout(back), q = pattern_from_layout(L);
      EXPECT_EQ(p.sets, q.sets) << c.file;
      EXPECT_EQ(p.weights, q.weights) << c.file;
    }
  }
}

// Every coordinate written, for every catalog pattern that fits every
// profile, is inside the API's legal range: D3D12 integers -8..7, the others
// multiples of 1/16 in [0, 0.9375].
TEST(ApiExport, EveryExportedCoordinateIsLegal) {
  int files = 0;
  for (const auto& [e, build] : pattern_registry().entries()) {
    if (e.name == "grid-NxN") continue;
    for (const ApiProfile& profile : api_profiles()) {
      std::string text;
      try {
        const HardwareLayout L =
            hardware_layout(snap_to_lattice(catalog_pattern(e.name), 16), profile);
        text = export_layout(L, default_shader(profile));
      } catch (const Error&) {
        continue;
      }
      ++files;
      const auto begin = text.find("aapat_sample_positions[");
      const std::string body = text.substr(text.find('{', begin) + 1,
                                           text.find("};", begin) - text.find('{', begin) - 1);
      int count = 0;
      for (const double v : numbers_in(body)) {
        ++count;
        if (profile.api == Api::kD3D12) {
          EXPECT_EQ(v, std::floor(v)) << e.name;
          EXPECT_GE(v, -8) << e.name;
          EXPECT_LE(v, 7) << e.name;
        } else {
          EXPECT_EQ(v * 16, std::floor(v * 16)) << e.name << " " << profile.name;
          EXPECT_GE(v, 0) << e.name;
          EXPECT_LE(v, 0.9375) << e.name << " " << profile.name;
        }
      }
      EXPECT_GT(count, 0) << e.name << " " << profile.name;
    }
  }
  EXPECT_GT(files, 40);
}

TEST(ApiExport, NumbersInSkipsCommentsAndIdentifiers) {
  EXPECT_EQ(numbers_in("{int3(0, -1, 2), 0.5f, // 7 8\n 1e-05, MTLSamplePositionMake(0.25, 1)}"),
            (std::vector<double>{0, -1, 2, 0.5, 1e-05, 0.25, 1}));
}

TEST(ApiExport, ImportRejectsDamagedText) {
  const std::string good = export_layout(layout_of(kCases[0]), ShaderLanguage::kHlsl);
  auto error_of = [](const std::string& text) {
    return testing::error_message([&] { parse_export(text, "x.txt"); });
  };
  EXPECT_NE(error_of("hello").find("import x.txt: the first line is not"), std::string::npos);
  std::string bad = good;
  bad.replace(bad.find("{-8, 3}"), 7, "{-9, 3}");
  EXPECT_EQ(error_of(bad),
            "import x.txt: sample position (-9, 3) is not a legal d3d12-tier2 lattice position");
  bad = good;
  bad.replace(bad.find("{0, 4, 8, 12, 16}"), 17, "{0, 4, 8, 12, 15}");
  EXPECT_EQ(error_of(bad),
            "import x.txt: the tap tables do not agree in size with each other and the grid");
  bad = good;
  bad.replace(bad.find("grid=2x2"), 8, "grid=3x3");
  EXPECT_NE(error_of(bad).find("grid 3x3"), std::string::npos);
}

// A name with a newline and a line of code, from any face, never becomes a
// line of the export: every language's comment stays one line, and a
// pattern file holding such a name is refused on read.
TEST(ApiExport, AHostileNameStaysInItsCommentInEveryLanguage) {
  Pattern p = catalog_pattern("rgss");
  p.name = "evil\n#define aapat_weights evil_weights\r\n#include <x>";
  for (const auto& [api, shader] : {std::pair{"d3d12-tier2", ShaderLanguage::kHlsl},
                                    {"vulkan", ShaderLanguage::kGlsl},
                                    {"metal", ShaderLanguage::kMsl}}) {
    const std::string code =
        export_pattern(p, api_profile(api), named_objective("laine-aila"), shader, true);
    EXPECT_EQ(code.find("\n#define aapat_weights"), std::string::npos) << api;
    EXPECT_EQ(code.find("\n#include <x>"), std::string::npos) << api;
    EXPECT_NE(code.find("evil #define aapat_weights"), std::string::npos) << api;
  }
  std::string text = pattern_to_json(catalog_pattern("rgss"));
  const size_t at = text.find("\"name\": \"rgss\"");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 14, "\"name\": \"rg\\nss\"");
  try {
    pattern_from_json(text, "p.json");
    FAIL() << "a name with a newline was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("name: control character U+000A at byte 2"),
              std::string::npos)
        << e.what();
  }
}

// The grid check both faces call: a fixed grid refused, a chosen grid held
// to 1 to max_grid pixels a side, naming what was given.
TEST(ApiExport, GridsAreCheckedOnce) {
  const ApiProfile& vulkan = api_profile("vulkan");
  EXPECT_NO_THROW(check_export_grid(vulkan, 2, 2, "--grid"));
  EXPECT_NO_THROW(check_export_grid(vulkan, vulkan.max_grid, 1, "--grid"));
  EXPECT_EQ(
      testing::error_message([] { check_export_grid(api_profile("d3d12-tier1"), 1, 1, "grid"); }),
      "grid: d3d12-tier1 has a fixed grid");
  EXPECT_NE(testing::error_message([&] {
              check_export_grid(vulkan, 0, 2, "grid");
            }).find("grid: 0x2; vulkan takes 1 to"),
            std::string::npos);
  EXPECT_THROW(check_export_grid(vulkan, vulkan.max_grid + 1, 1, "grid"), Error);
}

}  // namespace
}  // namespace aapat
