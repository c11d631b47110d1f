#include "aapat/io/aapat_catalog.h"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/pattern_json.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// Every embedded pattern loads, is valid, resolves by name like any catalog
// pattern, and has the E2 its provenance records under the objective it was
// optimized for (the lattice E2 for the API patterns) to the digits stored.
TEST(AapatCatalog, EveryPatternHasTheE2OfItsProvenance) {
  const std::vector<SpecInfo> entries = aapat_catalog();
  ASSERT_FALSE(entries.empty());
  const Metric recommended(make_filter("mitchell"), make_acuity("uniform:step=1"), 2);
  for (const SpecInfo& e : entries) {
    const Pattern p = resolve_pattern(e.name);
    EXPECT_EQ(p.name, e.name);
    const nlohmann::json doc = nlohmann::json::parse(pattern_to_json(p));
    const nlohmann::json& why = doc["provenance"];
    ASSERT_EQ(why.value("acuity", ""), "uniform:step=1,weight=1") << e.name;
    ASSERT_EQ(why.value("norm", ""), "2") << e.name;
    const double recorded = std::stod(why.value(why.contains("api") ? "lattice_e2" : "e2", "nan"));
    EXPECT_NEAR(recommended.evaluate(p).e2, recorded, 6e-6) << e.name;
    if (why.contains("api")) {
      // On the 1/16-pixel lattice.
      for (const auto& set : p.sets)
        for (const Vec2& v : set) {
          EXPECT_NEAR(v.x * 16, std::round(v.x * 16), 1e-9) << e.name;
          EXPECT_NEAR(v.y * 16, std::round(v.y * 16), 1e-9) << e.name;
        }
    }
  }
  EXPECT_TRUE(in_aapat_catalog("aapat-4"));
  EXPECT_NE(testing::error_message([] {
              aapat_catalog_pattern("aapat-99");
            }).find("unknown aapat catalog pattern 'aapat-99'"),
            std::string::npos);
}

// The names tell the truth: aapat-N[-API] is P(1,1,N), aapat-shared-N[-API]
// the sharing family P(4,1+,N), aapat-2x2-N[-API] the 2x2 kernels P(4,4,N),
// as `aapat list` shows them; and aapat-N keeps every sample strictly inside
// its pixel, so that plain MSAA can use it.
TEST(AapatCatalog, EveryNameMatchesItsFamilyAndItsSamplesAreWhereItSays) {
  int checked = 0;
  for (const SpecInfo& e : aapat_catalog()) {
    const Pattern p = resolve_pattern(e.name);
    std::string rest = e.name.substr(std::string("aapat-").size());
    std::string expected;
    bool one_pixel = false;
    if (rest.starts_with("shared-")) {
      rest = rest.substr(7);
      expected = "P(4,1+,";
    } else if (rest.starts_with("2x2-")) {
      rest = rest.substr(4);
      expected = "P(4,4,";
    } else if (rest.starts_with("quincunx-")) {  // corners shared by four pixels
      rest = rest.substr(9);
      expected = "P(1,1+,";
    } else {
      expected = "P(1,1,";
      one_pixel = true;
    }
    expected += rest.substr(0, rest.find('-')) + ")";
    EXPECT_EQ(family(p), expected) << e.name;
    EXPECT_NE(e.summary.find(expected), std::string::npos) << e.name << ": " << e.summary;
    if (one_pixel) {
      for (const auto& set : p.sets)
        for (const Vec2& v : set) {
          EXPECT_TRUE(std::abs(v.x) < 0.5 && std::abs(v.y) < 0.5)
              << e.name << ": (" << v.x << ", " << v.y << ") is not strictly inside the pixel";
        }
    }
    ++checked;
  }
  EXPECT_GE(checked, 100);
}

}  // namespace
}  // namespace aapat
