// The aapat catalog (data/patterns) against the published patterns, under
// the objective each entry was made for: the promise docs/catalog.md states.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/aapat_catalog.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/perceptual_objective.h"

namespace aapat {
namespace {

// The catalog's promise: under the objective it was made for, every free
// aapat pattern (no API suffix) is at least as good as every published or
// standard pattern of its family (Laine-Aila, Hasselgren, the MSAA and grid
// patterns of the pattern registry): the recommended E2 for the searches'
// results, the perceptual objective of its spec for a refined pattern. And a
// refined pattern's E2 stays at or below the standard one-pixel patterns' of
// its budget.
TEST(AapatCatalog, EveryFreePatternBeatsThePublishedOnesOfItsFamily) {
  const Metric recommended(make_filter("mitchell"), make_acuity("uniform:step=1"), 2);
  std::vector<std::pair<std::string, Pattern>> published;
  for (const auto& entry : pattern_registry().entries())
    if (entry.info.name != "grid-NxN")  // the family of grids: 2x2 to 4x4 below
      published.emplace_back(entry.info.name, catalog_pattern(entry.info.name));
  for (const char* grid : {"grid-3x3", "grid-4x4"})
    published.emplace_back(grid, catalog_pattern(grid));
  std::map<std::string, std::unique_ptr<PerceptualObjective>> perceptual;  // by spec
  int compared = 0, refined = 0;
  for (const SpecInfo& e : aapat_catalog()) {
    const Pattern p = resolve_pattern(e.name);
    const nlohmann::json why = nlohmann::json::parse(pattern_to_json(p))["provenance"];
    if (why.contains("api")) continue;
    std::function<double(const Pattern&)> objective = [&](const Pattern& q) {
      return recommended.evaluate(q).e2;
    };
    if (why.contains("refined")) {
      const std::string spec = why["refined"];
      auto& o = perceptual[spec];
      if (!o) o = std::make_unique<PerceptualObjective>(parse_perceptual(spec));
      objective = [&o](const Pattern& q) { return (*o)(q); };
      ++refined;
    }
    const double ours = objective(p);
    for (const auto& [name, q] : published)
      if (family(q) == family(p)) {
        EXPECT_LE(ours, objective(q) + 1e-9) << e.name << " against " << name;
        if (why.contains("refined") && family(p).starts_with("P(1,1,")) {
          EXPECT_LE(recommended.evaluate(p).e2, recommended.evaluate(q).e2) << e.name << " E2";
        }
        ++compared;
      }
  }
  EXPECT_GE(refined, 19);
  EXPECT_GE(compared, 20);
}

}  // namespace
}  // namespace aapat
