#include "aapat/temporal/engine/engine_json.h"

namespace aapat {

JsonObject engine_taa_json(std::string_view scene, const EngineRun& run, const Sequence& s,
                           const EngineTaa& taa, const EngineResult& r) {
  JsonObject doc = json_report("animate");
  JsonObject::array_t rows;
  for (const EngineFrame& f : r.frames)
    rows.push_back(JsonObject{{"rmse", f.rmse},
                              {"max_deviation", f.max_deviation},
                              {"flip", f.flip},
                              {"flicker", f.flicker},
                              {"ghosting", f.ghosting},
                              {"sharpness", f.sharpness}});
  doc.update(JsonObject{{"animation", scene},
                        {"motion", run.motion.spec},
                        {"pattern", s.name},
                        {"phases", s.period()},
                        {"taa", taa.preset},
                        {"taa_settings", engine_taa_text(taa)},
                        {"ratio", taa.upscale.ratio},
                        {"render_width", r.render_width},
                        {"render_height", r.render_height},
                        {"frames", run.frames},
                        {"warmup", run.warmup},
                        {"width", run.width},
                        {"height", run.height},
                        {"rmse", r.total.rmse},
                        {"max_deviation", r.total.max_deviation},
                        {"mean_flip", r.mean_flip},
                        {"flicker", r.flicker},
                        {"ghosting", r.ghosting},
                        {"sharpness", r.sharpness},
                        {"rows", rows}});
  // What the preset's engine would not run of the sequence, as the
  // comparison's document reports it.
  if (const auto w = engine_sequence_warnings(s, taa); !w.empty()) doc["warnings"] = w;
  return doc;
}

}  // namespace aapat
