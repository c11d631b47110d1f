#include "aapat/core/acuity.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/geometry.h"
#include "aapat/core/read_file.h"
#include "aapat/core/text.h"

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
constexpr double kMinStep = 180.0 / kMaxAcuityAngles;
double check_step(double step) {
  if (!(step >= kMinStep && step <= 90))
    throw Error(fmt::format(
        "acuity step {} is out of range [{}, 90] degrees (at most {} angles in [0, 180))", step,
        kMinStep, kMaxAcuityAngles));
  return step;
}
std::vector<double> angles_every(double step) {
  std::vector<double> a;
  for (int i = 0; i * step < 180 - 1e-9; ++i) a.push_back(i * step);
  return a;
}
// Angles that repeat modulo 180 (an edge direction is the same edge reversed):
// sorted, so a long table is checked in N log N.
template <class Where>
void check_repeats(const AcuityTable& t, Where where) {
  std::vector<std::pair<double, size_t>> reduced;
  for (size_t i = 0; i < t.angles_deg.size(); ++i) {
    double a = std::fmod(t.angles_deg[i], 180.0);
    if (a < 0) a += 180;
    reduced.emplace_back(a, i);
  }
  std::sort(reduced.begin(), reduced.end());
  for (size_t i = 0; i < reduced.size(); ++i) {
    const auto& [a, first] = reduced[i];
    const auto& [b, second] = reduced[(i + 1) % reduced.size()];
    const double gap = i + 1 < reduced.size() ? b - a : b + 180 - a;
    if (reduced.size() > 1 && gap < 1e-9) {
      const size_t earlier = std::min(first, second), later = std::max(first, second);
      throw Error(fmt::format("{}: angle {} repeats angle {} (edge directions repeat every 180)",
                              where(later), t.angles_deg[later], t.angles_deg[earlier]));
    }
  }
}

void check_some_weight_positive(const AcuityTable& t) {
  for (double w : t.weights)
    if (w > 0) return;
  throw Error(fmt::format("acuity table {}: every weight is 0, so every pattern scores 0", t.name));
}

}  // namespace

void validate(const AcuityTable& t) {
  const std::string& name = t.name;
  if (t.angles_deg.empty()) throw Error(fmt::format("acuity table {}: no angles", name));
  if (t.angles_deg.size() > static_cast<size_t>(kMaxAcuityAngles))
    throw Error(fmt::format("acuity table {}: {} angles exceed the limit of {}", name,
                            t.angles_deg.size(), kMaxAcuityAngles));
  if (t.weights.size() != t.angles_deg.size())
    throw Error(fmt::format("acuity table {}: {} angles but {} weights", name, t.angles_deg.size(),
                            t.weights.size()));
  for (size_t i = 0; i < t.angles_deg.size(); ++i) {
    if (!(t.angles_deg[i] >= -360 && t.angles_deg[i] <= 360))
      throw Error(fmt::format("acuity table {}: angle {} is out of range [-360, 360]", name,
                              t.angles_deg[i]));
    if (!(t.weights[i] >= 0 && t.weights[i] <= kMaxAcuityWeight))
      throw Error(fmt::format("acuity table {}: weight {} at angle {} is out of range [0, {}]",
                              name, t.weights[i], t.angles_deg[i], kMaxAcuityWeight));
  }
  check_some_weight_positive(t);
  check_repeats(t, [&](size_t i) { return fmt::format("acuity table {}, row {}", name, i + 1); });
}

AcuityTable uniform_acuity(double step_deg, double weight) {
  check_step(step_deg);
  if (!(weight > 0 && weight <= kMaxAcuityWeight))
    throw Error(
        fmt::format("uniform acuity: weight {} is out of range (0, {}]", weight, kMaxAcuityWeight));
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
  std::vector<int> lines;  // the line of each row, for messages
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
    if (t.angles_deg.size() >= static_cast<size_t>(kMaxAcuityAngles))
      throw Error(fmt::format("{}: more than {} rows, the limit", where, kMaxAcuityAngles));
    const double angle = parse_number(lv.substr(0, comma), where + ": angle");
    const double weight = parse_number(lv.substr(comma + 1), where + ": weight");
    if (!(angle >= -360 && angle <= 360))
      throw Error(fmt::format("{}: angle {} is out of range [-360, 360]", where, angle));
    if (!(weight >= 0 && weight <= kMaxAcuityWeight))
      throw Error(
          fmt::format("{}: weight {} is out of range [0, {}]", where, weight, kMaxAcuityWeight));
    t.angles_deg.push_back(angle);
    t.weights.push_back(weight);
    lines.push_back(line_no);
  }
  if (t.angles_deg.empty()) throw Error(fmt::format("acuity table {}: no rows", source));
  // Each row's range was checked as it was read; what is left spans rows.
  check_some_weight_positive(t);
  check_repeats(t,
                [&](size_t i) { return fmt::format("acuity table {} line {}", source, lines[i]); });
  return t;
}

const AcuityRegistry& acuity_registry() {
  static const AcuityRegistry kRegistry(
      "acuity",
      {{{"laine-aila",
         "4 edge angles: 0/90 deg weigh 3.93, 45/135 weigh 2.50 (default; data/README.md)",
         "Laine & Aila 2006, Sec. 4",
         {}},
        [](const Spec&) { return laine_aila_acuity(); }},
       {{"uniform",
         "every S degrees in [0, 180), all weights W",
         "aapat: an isotropic table",
         {{"step", "", "the angle step in degrees"}, {"weight", "1", "every angle's weight"}}},
        [](const Spec& s) { return uniform_acuity(s.number("step"), s.number("weight")); }},
       {{"linear",
         "every S degrees, laine-aila weights interpolated linearly between 45-degree nodes",
         "aapat: Laine & Aila's 4 angles, densified",
         {{"step", "", "the angle step in degrees"}}},
        [](const Spec& s) { return linear_acuity(s.number("step")); }}});
  return kRegistry;
}

AcuityTable make_acuity(std::string_view spec) {
  // A registered table by its spec, else a CSV file.
  if (acuity_registry().contains(spec)) return acuity_registry().make(spec);
  const std::string path(spec);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw Error(fmt::format(
        "unknown acuity table '{}': not laine-aila, uniform:step=S, linear:step=S or a readable "
        "CSV file",
        spec));
  return parse_acuity_csv(read_file(path, "acuity table", size_t{16} << 20), spec);
}

}  // namespace aapat
