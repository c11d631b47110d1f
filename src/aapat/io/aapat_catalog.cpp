#include "aapat/io/aapat_catalog.h"

#include <fmt/format.h>

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
    if (why.contains("refined"))
      summary += fmt::format(
          ", refined{} to {} under the perceptual objective",
          why.contains("refined_from") ? " from " + why.value("refined_from", "?") : std::string(),
          why.value("perceptual", "?"));
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
