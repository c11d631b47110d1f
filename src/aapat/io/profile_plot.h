// The per-angle error profile W(theta) E1(theta) of several patterns: one SVG
// line plot over edge angles 0..180 degrees, or the same numbers as CSV.
#pragma once

#include <string>
#include <vector>

#include "aapat/core/acuity.h"

namespace aapat {

struct ProfileSeries {
  std::string label;
  std::vector<double> values;  // one per acuity-table angle
};

std::string profile_svg(const AcuityTable& acuity, const std::vector<ProfileSeries>& series,
                        const std::string& title);
std::string profile_csv(const AcuityTable& acuity, const std::vector<ProfileSeries>& series);

}  // namespace aapat
