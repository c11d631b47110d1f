#include "aapat/io/json_report.h"

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

std::string json_text(const JsonObject& doc) {
  return doc.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace aapat
