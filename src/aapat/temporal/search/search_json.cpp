#include "aapat/temporal/search/search_json.h"

#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {

JsonObject pan_search_json(const PanSequenceSearch& search, const Objective& objective,
                           const PanSequenceSearchResult& r) {
  JsonObject doc = json_report("optimize");
  doc.update(objective_json(objective));
  JsonObject::array_t velocities;
  for (size_t i = 0; i < r.velocities.size(); ++i)
    velocities.push_back(JsonObject{{"velocity", {r.velocities[i].x, r.velocities[i].y}},
                                    {"start_mean_e2", r.start_values[i]},
                                    {"mean_e2", r.values[i]}});
  doc.update(JsonObject{{"frames", search.start.period()},
                        {"taa", search.taa.preset},
                        {"taa_settings", engine_taa_text(search.taa)},
                        {"ratio", search.taa.upscale.ratio},
                        {"from", search.start.name},
                        {"step", search.step},
                        {"min_step", search.min_step},
                        {"jitter_bound", search.jitter_bound},
                        {"start_mean_e2", r.start_value},
                        {"mean_e2", r.value},
                        {"velocities", velocities},
                        {"tries", r.tries},
                        {"kept", r.kept}});
  doc["result"] = JsonObject::parse(sequence_to_json(r.best));
  return doc;
}

JsonObject sequence_search_json(const SequenceSearch& s, std::string_view model,
                                const Objective& objective, const SequenceSearchResult& r) {
  JsonObject doc = json_report("optimize");
  doc.update(JsonObject{
      {"frames", s.frames},
      {"samples_per_frame", s.samples_per_frame},
      {"model", model},
      {"flicker_weight", s.flicker_weight},
      {"jitter_bound", s.jitter_bound},
      {"jitter_radius", s.jitter_radius ? JsonObject(*s.jitter_radius) : JsonObject(nullptr)}});
  doc.update(objective_json(objective));
  doc.update(JsonObject{{"seed", s.seed},
                        {"starts", s.starts},
                        {"iterations", s.iterations},
                        {"best_start", r.best_start},
                        {"j", r.objective},
                        {"frame_measure", frame_measure_name(s.frame_measure)},
                        {"worst_e2", r.worst_e2},
                        {"mean_e2", r.mean_e2},
                        {"flicker", r.flicker},
                        {"halton_j", r.halton_objective}});
  if (r.continuous_objective) doc["continuous_j"] = *r.continuous_objective;
  if (s.upscale) {
    doc["ratio"] = s.upscale->ratio;
    doc["reconstruction"] = s.upscale->reconstruction.name();
  }
  doc["result"] = JsonObject::parse(sequence_to_json(r.best));
  return doc;
}

}  // namespace aapat
