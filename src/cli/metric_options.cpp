#include "cli/metric_options.h"

#include "aapat/core/filter_catalog.h"

namespace aapat {

void MetricOptions::add_to(CLI::App* cmd) {
  cmd->add_option("--filter,-f", filter,
                  "reference filter, e.g. mitchell:b=1/3,c=1/3, gaussian:sigma=0.5,radius=1.5, "
                  "lanczos:lobes=3 (see `aapat list`)")
      ->capture_default_str();
  cmd->add_option("--acuity,-a", acuity,
                  "acuity table: laine-aila, uniform:step=S, linear:step=S or a CSV file")
      ->capture_default_str();
  cmd->add_option("--norm,-p", norm,
                  "p of the L_p mean over angles; inf is the maximum of Laine-Aila Eq. 5")
      ->capture_default_str();
}

Metric MetricOptions::make() const {
  return Metric(make_filter(filter), make_acuity(acuity), parse_norm(norm, "--norm"));
}

}  // namespace aapat
