#include "core/acuity.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/filter_catalog.h"
#include "core/geometry.h"
#include "core/text.h"

namespace aapat {

namespace embedded {
extern const std::string_view kAcuityLaineAilaCsv;
}

AcuityTable laine_aila_acuity() {
  AcuityTable t = parse_acuity_csv(embedded::kAcuityLaineAilaCsv, "laine-aila");
  t.name = "laine-aila";
  return t;
}

namespace {
double check_step(double step) {
  if (!(step > 0 && step <= 90 && std::isfinite(step)))
    throw Error(fmt::format("acuity step {} is out of range (0, 90] degrees", step));
  return step;
}
std::vector<double> angles_every(double step) {
  std::vector<double> a;
  for (int i = 0; i * step < 180 - 1e-9; ++i) a.push_back(i * step);
  return a;
}
}  // namespace

AcuityTable uniform_acuity(double step_deg, double weight) {
  check_step(step_deg);
  if (!(weight > 0 && std::isfinite(weight)))
    throw Error(fmt::format("uniform acuity: weight {} must be positive", weight));
  AcuityTable t{
      fmt::format("uniform:step={},weight={}", step_deg, weight), angles_every(step_deg), {}};
  t.weights.assign(t.angles_deg.size(), weight);
  return t;
}

AcuityTable linear_acuity(double step_deg) {
  check_step(step_deg);
  const AcuityTable base = laine_aila_acuity();
  const double w_axis = base.weights[0], w_diag = base.weights[1];
  AcuityTable t{fmt::format("linear:step={}", step_deg), angles_every(step_deg), {}};
  for (double a : t.angles_deg) {
    const double m = std::fmod(a, 90.0);
    const double d = m <= 45 ? m / 45 : (90 - m) / 45;  // 0 on an axis, 1 on a diagonal
    t.weights.push_back(w_axis + (w_diag - w_axis) * d);
  }
  return t;
}

AcuityTable parse_acuity_csv(std::string_view text, std::string_view source) {
  AcuityTable t{std::string(source), {}, {}};
  std::istringstream in{std::string(text)};
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto comma = line.find(',');
    if (comma == std::string::npos || line.find(',', comma + 1) != std::string::npos)
      throw Error(fmt::format("acuity table {} line {}: expected 'angle,weight', got '{}'", source,
                              line_no, line));
    const std::string where = fmt::format("acuity table {} line {}", source, line_no);
    std::string_view lv(line);
    const double angle = parse_number(lv.substr(0, comma), where + ": angle");
    const double weight = parse_number(lv.substr(comma + 1), where + ": weight");
    if (weight < 0) throw Error(fmt::format("{}: weight {} is negative", where, weight));
    for (double a : t.angles_deg) {
      const double diff = std::fmod(std::abs(a - angle), 180.0);
      if (diff < 1e-9 || 180.0 - diff < 1e-9)
        throw Error(fmt::format("{}: angle {} repeats angle {} (edge directions repeat every 180)",
                                where, angle, a));
    }
    t.angles_deg.push_back(angle);
    t.weights.push_back(weight);
  }
  if (t.angles_deg.empty()) throw Error(fmt::format("acuity table {}: no rows", source));
  return t;
}

AcuityTable make_acuity(std::string_view spec) {
  if (spec == "laine-aila") return laine_aila_acuity();
  const auto colon = spec.find(':');
  const std::string_view kind = spec.substr(0, colon);
  if ((kind == "uniform" || kind == "linear") && colon != std::string_view::npos) {
    double step = 0, weight = 1;
    bool has_step = false;
    for (const std::string_view item : split(spec.substr(colon + 1))) {
      const auto eq = item.find('=');
      const std::string_view key = item.substr(0, eq);
      if (eq == std::string_view::npos ||
          !(key == "step" || (key == "weight" && kind == "uniform")))
        throw Error(fmt::format("acuity {}: unknown parameter '{}' (it takes step{})", kind, item,
                                kind == "uniform" ? " and weight" : ""));
      (key == "step" ? step : weight) = parse_number(item.substr(eq + 1), key);
      has_step = has_step || key == "step";
    }
    if (!has_step)
      throw Error(fmt::format("acuity {}: give the angle step, e.g. {}:step=1", kind, kind));
    return kind == "uniform" ? uniform_acuity(step, weight) : linear_acuity(step);
  }
  std::ifstream file{std::string(spec)};
  if (!file)
    throw Error(fmt::format(
        "unknown acuity table '{}': not laine-aila, uniform:step=S, linear:step=S or a readable "
        "CSV file",
        spec));
  std::stringstream buffer;
  buffer << file.rdbuf();
  return parse_acuity_csv(buffer.str(), spec);
}

const std::vector<AcuityInfo>& acuity_catalog() {
  static const std::vector<AcuityInfo> kInfo = {
      {"laine-aila",
       "4 edge angles: 0/90 deg weigh 3.93, 45/135 weigh 2.50 (default; data/README.md)"},
      {"uniform:step=S[,weight=W]", "every S degrees in [0, 180), all weights W (default 1)"},
      {"linear:step=S",
       "every S degrees, laine-aila weights interpolated linearly between 45-degree nodes"},
      {"FILE.csv", "rows 'edge_angle_deg,weight'; '#' starts a comment"},
  };
  return kInfo;
}

}  // namespace aapat
