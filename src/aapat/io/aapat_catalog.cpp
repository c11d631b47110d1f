#include "aapat/io/aapat_catalog.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <utility>

#include "aapat/core/objective.h"
#include "aapat/io/pattern_json.h"

namespace aapat::embedded {
extern const std::vector<std::pair<std::string_view, std::string_view>> kAapatPatterns;
}  // namespace aapat::embedded

namespace aapat {

std::vector<SpecInfo> aapat_catalog() {
  std::vector<SpecInfo> out;
  for (const auto& [name, text] : embedded::kAapatPatterns) {
    const nlohmann::json doc = nlohmann::json::parse(text);
    const nlohmann::json& why = doc.value("provenance", nlohmann::json::object());
    // The family of the samples themselves, and the objective it was
    // designed for, from its provenance.
    const Pattern p = pattern_from_json(text, fmt::format("data/patterns/{}.json", name));
    const std::optional<Objective> designed = design_objective(p);
    std::string summary = fmt::format("{}: E2 {} under the objective {}", family(p),
                                      why.value("e2", "?"), designed ? designed->text() : "?");
    const std::string from =
        why.contains("refined_from") ? " from " + why.value("refined_from", "?") : std::string();
    if (why.contains("perceptual"))
      summary += fmt::format(", refined{} to {} under the perceptual objective", from,
                             why.value("perceptual", "?"));
    if (why.contains("rendered"))
      summary += fmt::format(", {} to {} under the mean {}",
                             why.contains("perceptual") ? "then" : "refined" + from,
                             why.value("rendered", "?"), why.value("refined", "?"));
    if (why.contains("api"))
      summary += fmt::format(", on {}'s lattice E2 {}", why.value("api", "?"),
                             why.value("lattice_e2", "?"));
    out.push_back({std::string(name),
                   summary,
                   fmt::format("aapat catalog: data/patterns/{}.json", name),
                   {}});
  }
  return out;
}

std::vector<BestAtCost> best_per_cost() {
  std::vector<BestAtCost> out;
  for (const auto& [name, text] : embedded::kAapatPatterns) {
    const nlohmann::json why =
        nlohmann::json::parse(text).value("provenance", nlohmann::json::object());
    if (why.contains("api") || !why.contains("rendered")) continue;
    const Pattern p = pattern_from_json(text, fmt::format("data/patterns/{}.json", name));
    const double cost = samples_per_pixel(p), value = std::stod(why.value("rendered", "inf"));
    auto it =
        std::find_if(out.begin(), out.end(), [&](const BestAtCost& b) { return b.cost == cost; });
    if (it == out.end()) {
      out.push_back({cost, std::string(name), value, {}});
      it = out.end() - 1;
    } else if (value < it->value) {
      it->rivals.push_back(it->name);
      it->name = std::string(name), it->value = value;
      continue;
    }
    if (it->name != name) it->rivals.push_back(std::string(name));
  }
  std::sort(out.begin(), out.end(),
            [](const BestAtCost& a, const BestAtCost& b) { return a.cost < b.cost; });
  for (BestAtCost& b : out) std::sort(b.rivals.begin(), b.rivals.end());
  return out;
}

std::vector<SpecInfo> best_per_cost_infos() {
  std::vector<SpecInfo> out;
  for (const BestAtCost& b : best_per_cost())
    out.push_back(
        {b.name,
         fmt::format("cost {:g}: mean FLIP {:.6f} on the tuning views{}", b.cost, b.value,
                     b.rivals.empty() ? std::string()
                                      : fmt::format(" (beside {})", fmt::join(b.rivals, ", "))),
         "docs/catalog.md",
         {}});
  return out;
}

bool in_aapat_catalog(std::string_view name) {
  for (const auto& entry : embedded::kAapatPatterns)
    if (entry.first == name) return true;
  return false;
}

Pattern aapat_catalog_pattern(std::string_view name) {
  for (const auto& [n, text] : embedded::kAapatPatterns)
    if (n == name) {
      Pattern p = pattern_from_json(text, fmt::format("data/patterns/{}.json", n));
      p.name = std::string(n);
      return p;
    }
  throw Error(fmt::format("unknown aapat catalog pattern '{}' (aapat list shows them)", name));
}

}  // namespace aapat
