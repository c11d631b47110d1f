#include "aapat/registry/spec_registries.h"

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/objective.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/aapat_catalog.h"
#include "aapat/render/motion.h"
#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"
#include "aapat/study/perceptual_objective.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {
namespace {

template <class R>
RegistrySection section(std::string key, std::string heading, const R& registry) {
  RegistrySection s{std::move(key), std::move(heading), {}};
  for (const auto& e : registry.entries()) s.infos.push_back(e.info);
  return s;
}

std::vector<SpecInfo> preset_infos() {
  std::vector<SpecInfo> out;
  for (const EnginePresetInfo& p : engine_presets())
    out.push_back({p.name, p.summary, p.source, {}});
  return out;
}

}  // namespace

std::vector<RegistrySection> registry_sections() {
  return {
      RegistrySection{"objectives",
                      "objectives (--objective; or 'filter=F acuity=A norm=P', starting from "
                      "recommended; perceptual: aapat eval, refine, study --perceptual)",
                      [] {
                        std::vector<SpecInfo> all = objective_infos();
                        all.push_back(perceptual_info());
                        return all;
                      }()},
      section("patterns", "patterns", pattern_registry()),
      RegistrySection{"aapat_patterns",
                      "the aapat catalog (data/patterns: the best found per budget and API, "
                      "docs/catalog.md)",
                      aapat_catalog()},
      RegistrySection{"best_patterns",
                      "the best pattern per cost, any family (the lowest mean FLIP on the "
                      "tuning views, docs/catalog.md)",
                      best_per_cost_infos()},
      section("filters", "filters", filter_registry()),
      section("generators", "point generators (aapat generate, spectrum, discrepancy)",
              generator_registry()),
      section("acuity_tables", "acuity tables (or a CSV file of 'edge_angle_deg,weight' rows)",
              acuity_registry()),
      section("scenes", "scenes (aapat render; or a .json scene file, docs/renderer.md)",
              scene_registry()),
      section("textures", "textures (aapat render --texture; or a .png file)", texture_registry()),
      section("texture_filters", "texture filters (aapat render --texture-filter)",
              texture_filter_registry()),
      section("api_profiles", "API profiles (aapat export --api, optimize --api)",
              profile_registry()),
      section("motions", "motions (aapat animate SCENE --motion, docs/temporal.md)",
              motion_registry()),
      section("sequences",
              "sequences (aapat sequence, animate --sequence; or a .json sequence file)",
              sequence_registry()),
      RegistrySection{"aapat_sequences", "optimized sequences (data/sequences, docs/temporal.md)",
                      sequence_catalog()},
      RegistrySection{"taa_presets",
                      "engine TAA presets (aapat animate SCENE --taa, docs/temporal.md)",
                      preset_infos()}};
}

JsonObject spec_info_json(const SpecInfo& info) {
  JsonObject params = JsonObject::array();
  for (const ParamInfo& p : info.params)
    params.push_back(
        {{"key", p.key},
         {"default", p.default_text.empty() ? JsonObject() : JsonObject(p.default_text)},
         {"meaning", p.meaning}});
  return {{"name", info.name},
          {"usage", info.usage()},
          {"summary", info.summary},
          {"source", info.source},
          {"parameters", params}};
}

JsonObject registry_json() {
  JsonObject doc = JsonObject::object();
  for (const RegistrySection& s : registry_sections()) {
    JsonObject entries = JsonObject::array();
    for (const SpecInfo& info : s.infos) entries.push_back(spec_info_json(info));
    doc[s.key] = std::move(entries);
  }
  return doc;
}

}  // namespace aapat
