#include "aapat/temporal/temporal_json.h"

#include "aapat/temporal/pan_distribution.h"
#include "aapat/temporal/sequence_json.h"

namespace aapat {

JsonObject temporal_report_json(const Sequence& s, const TemporalReport& r) {
  JsonObject::array_t prefixes;
  for (const PrefixMeasure& p : r.prefixes)
    prefixes.push_back(JsonObject{{"samples", p.samples},
                                  {"most_in_x", p.most_in_x},
                                  {"most_in_y", p.most_in_y},
                                  {"star", p.star},
                                  {"l2_star", p.l2_star}});
  return JsonObject{{"sequence", s.name},
                    {"frames", s.period()},
                    {"family", family(s.frames[0])},
                    {"worst_e2", r.worst_e2},
                    {"mean_e2", r.mean_e2},
                    {"steady_e2", r.steady_e2},
                    {"cut_curve", r.cut_curve},
                    {"settle_frame", r.settle_frame},
                    {"flicker", r.mean_flicker},
                    {"worst_flicker", r.worst_flicker},
                    {"flicker_per_transition", r.flicker},
                    {"mean_offset", JsonObject::array({r.mean_offset.x, r.mean_offset.y})},
                    {"worst_centroid", r.worst_centroid},
                    {"prefixes", prefixes}};
}

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
                        {"ratio", search.taa.ratio},
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
                        {"frame_measure", s.frame_measure == FrameMeasure::mean ? "mean" : "worst"},
                        {"worst_e2", r.worst_e2},
                        {"mean_e2", r.mean_e2},
                        {"flicker", r.flicker},
                        {"halton_j", r.halton_objective}});
  if (r.continuous_objective) doc["continuous_j"] = *r.continuous_objective;
  if (s.reconstruction) {
    doc["ratio"] = s.ratio;
    doc["reconstruction"] = s.reconstruction->name();
  }
  doc["result"] = JsonObject::parse(sequence_to_json(r.best));
  return doc;
}

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
                        {"ratio", taa.ratio},
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
  return doc;
}

JsonObject::array_t pan_rows_json(const std::vector<Sequence>& sequences,
                                  const std::vector<Vec2>& velocities,
                                  const std::vector<std::vector<PanReport>>& reports) {
  JsonObject::array_t rows;
  const auto n = static_cast<double>(velocities.size());
  for (size_t i = 0; i < sequences.size(); ++i) {
    JsonObject::array_t per;
    double e2 = 0, flicker = 0;
    for (size_t k = 0; k < velocities.size(); ++k) {
      per.push_back({{"velocity", {velocities[k].x, velocities[k].y}},
                     {"mean_e2", reports[i][k].mean_e2},
                     {"flicker", reports[i][k].flicker}});
      e2 += reports[i][k].mean_e2 / n;
      flicker += reports[i][k].flicker / n;
    }
    JsonObject row{{"sequence", sequences[i].name},
                   {"phases", sequences[i].period()},
                   {"mean_e2", e2},
                   {"flicker", flicker},
                   {"velocities", per}};
    if (i > 0) {
      const PanComparison c = compare_pans(reports[i], reports[0]);
      row["against_first"] = {
          {"sequence", sequences[0].name},    {"lower_at", c.lower},
          {"velocities", c.velocities},       {"mean_change", c.mean_change},
          {"lowest_change", c.lowest_change}, {"highest_change", c.highest_change}};
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace aapat
