// The enumeration of Hasselgren et al. Sec. 5: every placement configuration
// of the mirrored P(4,1+,n) family for the given costs, optionally optimized
// from random starts and ranked by E2 within each cost.
#pragma once

#include <vector>

#include "aapat/core/metric.h"
#include "aapat/generate/enumerate.h"
#include "aapat/study/progress.h"

namespace aapat {

struct EnumerationSettings {
  std::vector<double> costs{1.25, 1.5, 1.75, 2};
  EnumerationRules rules;
  bool optimize = false;
  int starts = 32;  // per configuration
  uint64_t seed = 1;
};

struct EnumerationRow {
  int id = 0;  // numbered in enumeration order, kept through the ranking
  double n = 0;
  PlacementConfig config;
  double e2 = NAN;  // when optimized
  Pattern best;     // when optimized: named, with provenance
};

struct Enumeration {
  std::vector<EnumerationRow> rows;            // by cost, then (optimized) by E2
  int count(double n) const;                   // configurations of cost n
  const EnumerationRow* best(double n) const;  // the first row of cost n
};

Enumeration enumerate_study(const Metric& metric, const EnumerationSettings& settings,
                            const StudyProgress& progress = {});

}  // namespace aapat
