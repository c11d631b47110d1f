// Angle acuity tables W(theta) of the E2 metric (Laine-Aila Eq. 5, after
// Naiman 1998). Angles are edge directions in degrees, counter-clockwise from
// the x axis; E2 is evaluated at exactly the table's angles.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/spec.h"

namespace aapat {

struct AcuityTable {
  std::string name;
  std::vector<double> angles_deg;  // edge directions
  std::vector<double> weights;     // W(theta) >= 0, one per angle
};

// Limits every table meets (docs/limits.md): checked before anything is allocated.
inline constexpr int kMaxAcuityAngles = 36000;  // a step of 0.005 degrees
inline constexpr double kMaxAcuityWeight = 1e6;

// Throws Error naming the table and the row unless: 1 to kMaxAcuityAngles
// angles, each finite in [-360, 360] and none repeating another modulo 180;
// weights finite in [0, kMaxAcuityWeight], at least one positive.
void validate(const AcuityTable& table);

// The table that reproduces both papers' published E2 values (data/README.md):
// 0 and 90 degrees weigh 3.93, 45 and 135 weigh 2.50.
AcuityTable laine_aila_acuity();
// Every `step_deg` degrees in [0, 180), all weights `weight`.
AcuityTable uniform_acuity(double step_deg, double weight = 1.0);
// Every `step_deg` degrees, the Laine-Aila weights interpolated linearly in
// angle between their 45-degree nodes: a finer table of the same shape.
AcuityTable linear_acuity(double step_deg);
// Rows "angle,weight"; '#' starts a comment. `source` names the text in errors.
AcuityTable parse_acuity_csv(std::string_view text, std::string_view source);

// `laine-aila` (default), `uniform:step=S[,weight=W]`, `linear:step=S`, or a CSV file path.
AcuityTable make_acuity(std::string_view spec);

inline constexpr std::string_view kDefaultAcuity = "laine-aila";

// laine-aila, uniform:step=S[,weight=W], linear:step=S (core/spec.h); any
// other spec names a CSV file of rows 'edge_angle_deg,weight'.
using AcuityRegistry = Registry<AcuityTable>;
const AcuityRegistry& acuity_registry();

}  // namespace aapat
