// Jobs on one pattern or a published list of them: snapping to the
// programmable-position lattice (what it costs in E2), and Hasselgren et al.
// Table 2 re-measured on the translating-circle animation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/render/animation.h"
#include "aapat/study/progress.h"

namespace aapat {

struct SnapResult {
  Pattern snapped;  // named NAME-latticeN; weights re-optimized when asked
  double e2_before = 0, e2_snapped = 0;
  std::optional<double> e2_optimized_weights;
  double largest_move = 0;  // pixels
};
// Every sample to its nearest lattice point; then, with optimize_weights,
// weights optimized for the snapped positions (non-negative when asked).
SnapResult snap_study(const Metric& metric, const Pattern& pattern, int steps,
                      bool optimize_weights, bool nonnegative);

struct Table2Row {
  std::string pattern, label;
  double e2 = 0, rmse = 0;
  int max_deviation = 0;
  double paper_e2 = 0, paper_rmse = 0;  // Hasselgren et al. Table 2
  int paper_max_deviation = 0;
};
// The nine patterns of Hasselgren Table 2: E2 with the default metric, RMSE
// and max deviation over the animation `settings` (the translating circle).
std::vector<Table2Row> table2(const AnimationSettings& settings,
                              const ReferenceSource& references = render_reference,
                              const StudyProgress& progress = {});

}  // namespace aapat
