#include "aapat/temporal/model/model_json.h"

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

}  // namespace aapat
