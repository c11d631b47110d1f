#include "aapat/temporal/engine/engine_pans.h"

#include <fmt/format.h>

#include <mutex>

#include <tbb/parallel_for.h>

namespace aapat {

PanModel pan_model_of(const EngineTaa& taa, Vec2 velocity) {
  PanModel m;
  m.upscale = taa.upscale;
  m.history = taa.history;
  m.velocity = velocity;
  return m;
}

PanTable evaluate_pans(const std::vector<Sequence>& sequences, const EngineTaa& taa,
                       const std::vector<Vec2>& velocities, const Metric& metric,
                       const ItemsProgress& progress) {
  for (const Vec2 v : velocities) check_velocity(v);  // before any work starts
  PanTable table;
  table.velocities = velocities;
  table.rows.resize(sequences.size());
  for (size_t i = 0; i < sequences.size(); ++i) {
    table.rows[i].sequence = sequences[i].name;
    table.rows[i].phases = sequences[i].period();
    table.rows[i].at.resize(velocities.size());
  }
  const size_t pairs = sequences.size() * velocities.size();
  std::mutex reporting;
  int done = 0;
  tbb::parallel_for(size_t{0}, pairs, [&](size_t at) {
    const size_t i = at / velocities.size(), k = at % velocities.size();
    const Vec2 v = velocities[k];
    const PanModel m = pan_model_of(taa, v);
    table.rows[i].at[k] = evaluate_pan(engine_samples(sequences[i], taa), m,
                                       steady_alpha(taa, v.x != 0 || v.y != 0), metric);
    if (!progress) return;
    const std::lock_guard lock(reporting);
    progress(++done, static_cast<int>(pairs),
             fmt::format("{} at {:g},{:g}", sequences[i].name, v.x, v.y));
  });
  const auto n = static_cast<double>(velocities.size());
  for (PanRow& row : table.rows) {
    for (const PanReport& r : row.at) {
      row.mean.mean_e2 += r.mean_e2 / n;
      row.mean.flicker += r.flicker / n;
    }
  }
  for (size_t i = 1; i < table.rows.size(); ++i)
    table.rows[i].against_first = compare_pans(table.rows[i].at, table.rows[0].at);
  return table;
}

JsonObject::array_t pan_rows_json(const PanTable& table) {
  JsonObject::array_t rows;
  for (const PanRow& r : table.rows) {
    JsonObject::array_t per;
    for (size_t k = 0; k < table.velocities.size(); ++k)
      per.push_back({{"velocity", {table.velocities[k].x, table.velocities[k].y}},
                     {"mean_e2", r.at[k].mean_e2},
                     {"flicker", r.at[k].flicker}});
    JsonObject row{{"sequence", r.sequence},
                   {"phases", r.phases},
                   {"mean_e2", r.mean.mean_e2},
                   {"flicker", r.mean.flicker},
                   {"velocities", per}};
    if (r.against_first) {
      const PanComparison& c = *r.against_first;
      row["against_first"] = {
          {"sequence", table.rows[0].sequence}, {"lower_at", c.lower},
          {"velocities", c.velocities},         {"mean_change", c.mean_change},
          {"lowest_change", c.lowest_change},   {"highest_change", c.highest_change}};
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace aapat
