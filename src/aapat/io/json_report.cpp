#include "aapat/io/json_report.h"

#include "aapat/analyze/paired_comparison.h"

namespace aapat {

JsonObject json_report(std::string_view command) {
  return JsonObject{{"command", std::string(command)}, {"schema", kJsonSchema}};
}

JsonObject objective_json(const Objective& objective) {
  return JsonObject{{"objective", objective.text()},
                    {"filter", objective.filter},
                    {"acuity", objective.acuity},
                    {"norm", format_norm(objective.norm)}};
}

JsonObject paired_comparison_json(const PairedComparison& c) {
  return JsonObject{{"lower", c.lower},
                    {"ties", c.ties},
                    {"scenes", c.items},
                    {"mean_difference", c.mean_difference},
                    {"low", c.low},
                    {"high", c.high},
                    {"mean_ratio", c.mean_ratio},
                    {"sign_p", c.sign_p}};
}

std::string json_text(const JsonObject& doc) {
  return doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace aapat
