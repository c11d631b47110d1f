#include "cli/metric_options.h"

#include <fmt/format.h>

#include <optional>

namespace aapat {

void MetricOptions::add_to(CLI::App* cmd, std::string_view default_objective) {
  objective = std::string(default_objective);
  cmd->add_option("--objective,-O", objective,
                  fmt::format("what E2 means: {} (the study's, the catalog's), {} (the papers'), "
                              "or 'filter=F acuity=A norm=P' (see `aapat list`)",
                              kRecommendedObjective, kPapersObjective))
      ->capture_default_str();
  cmd->add_option("--filter,-f", filter,
                  "the objective's reference filter instead, e.g. mitchell:b=1/3,c=1/3, "
                  "gaussian:sigma=0.5,radius=1.5, lanczos:lobes=3");
  cmd->add_option("--acuity,-a", acuity,
                  "the objective's acuity table instead: laine-aila, uniform:step=S, "
                  "linear:step=S or a CSV file");
  cmd->add_option("--norm,-p", norm,
                  "the objective's p of the L_p mean over angles instead; inf is the maximum of "
                  "Laine-Aila Eq. 5");
}

Objective MetricOptions::resolve() const {
  const auto given = [](const std::string& s) {
    return s.empty() ? std::nullopt : std::optional<std::string>(s);
  };
  std::optional<double> p;
  if (!norm.empty()) p = parse_norm(norm, "--norm");
  return override_objective(parse_objective(objective, "--objective"), given(filter), given(acuity),
                            p);
}

}  // namespace aapat
