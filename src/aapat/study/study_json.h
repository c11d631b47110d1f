// The JSON document of each study's result (docs/json.md), made once: the
// command's --json prints it, its text and CSV tables are printed from it,
// and the Python function returns it (or its rows) with the same keys.
// eval_json, optimize_run_json and the temporal documents live beside
// their studies; these are the rest.
#pragma once

#include <string>
#include <vector>

#include "aapat/core/objective.h"
#include "aapat/io/json_report.h"
#include "aapat/study/enumeration.h"
#include "aapat/study/image_diff.h"
#include "aapat/study/objective_study.h"
#include "aapat/study/paper_tables.h"
#include "aapat/study/pattern_studies.h"
#include "aapat/study/point_set_study.h"
#include "aapat/study/render_study.h"

namespace aapat {

// Laine-Aila Table 3: rows {distribution, min, avg, max, opt_w, opt_wp,
// paper: [the five published numbers]}.
JsonObject table3_json(const Objective& objective, const Table3Settings& settings,
                       const std::vector<Table3Row>& rows);

// Laine-Aila Figure 10: rows {family, n, e2, placement ("" all inside), series}.
JsonObject figure10_json(const Objective& objective, const Figure10Settings& settings,
                         const Figure10& figure);

// The lattice's cost: rows {n, pattern, profile, layout, e2_continuous, e2_lattice}.
JsonObject hardware_table_json(const Objective& objective, const HardwareTableSettings& settings,
                               const std::vector<HardwareTableRow>& rows);

// Hasselgren Table 2: rows {pattern, label, e2, rmse, max_deviation,
// paper: {e2, rmse, max_deviation}}, E2 under the papers' objective.
JsonObject table2_json(const AnimationSettings& settings, const std::vector<Table2Row>& rows);

// The P(4,1+,n) enumeration: rows {id, n, placement, samples_read, e2 (null
// unless optimized)}.
JsonObject enumeration_json(const Objective& objective, const EnumerationSettings& settings,
                            const Enumeration& enumeration);

// A pattern snapped to the lattice: e2_before, e2_snapped, largest_move,
// family, n[, e2_optimized_weights].
JsonObject snap_json(const Objective& objective, const std::string& pattern, int lattice,
                     const SnapResult& result);

// The discrepancies asked of a point set: points, then l2_star, ...,
// star_lower, star_upper, star_exact, star_gap, edge, edge_normal_deg, as
// computed. `source` names the set ("" leaves it out: Python's array).
JsonObject discrepancy_json(const std::string& source, const DiscrepancyReport& report);

// A rendering's shading and lookups: mode, shading_point, texture_filter,
// lookups_per_pixel, shadings_per_pixel.
JsonObject shading_json(const Sampling& sampling, const RenderStats& stats);
// Its refinement: criterion, threshold, max_depth, max_samples, per_square,
// average_samples, refined_fraction, evaluations.
JsonObject adaptive_json(const AdaptiveSettings& settings, const AdaptiveImage& result);
// Its error figures: rmse, max_deviation, ssim (null below one SSIM
// window), flip (the mean FLIP).
JsonObject figures_json(const RenderFigures& figures);

// One cell of `aapat render --grid --json`: the row's pattern (or generator
// and samples), the column's filter, samples per pixel, the shading, the
// refinement when adaptive, and the figures.
JsonObject grid_cell_json(const RenderGridCell& cell);

// `aapat render --grid --json`: the scene, texture (null: none), size and
// reference, and a row per cell that is not a refinement map's.
JsonObject render_grid_json(const std::string& scene_name, const std::string& texture, int width,
                            int height, const ReferenceSettings& reference,
                            const std::vector<RenderGridCell>& cells);

// `aapat study --compare --json`: the objectives' names, scenes, measures,
// patterns [{pattern, objectives, measures (per scene)}], and each pattern
// after the first against the first: against_first [{pattern, against,
// MEASURE: paired_comparison_json}].
JsonObject study_compare_json(const StudySettings& settings,
                              const std::vector<StudyObjective>& objectives,
                              const std::vector<StudyPattern>& patterns);

// `aapat spectrum --1d --json`: the kinds, points, seed, frequencies and
// max_frequency, and a row per frequency {frequency, KIND: power, ...}.
JsonObject line_spectra_json(const std::vector<std::string>& kinds, uint64_t seed, int frequencies,
                             double max_frequency, const std::vector<LineSpectrum>& spectra);

// One rendering (`aapat render --json`, aapat.render's values): scene,
// texture, width, height, pattern (or generator and samples), filter,
// samples_per_pixel, the shading keys, adaptive {...} when refined, and when
// measured reference, rmse, max_deviation, ssim, flip; channels (1 grey, 3
// colour), and for a mesh scene model {file, triangles, vertices, materials,
// textured_materials, warnings}. `scene_name`, `texture` and `pattern` are the
// names the caller gave.
JsonObject render_json(const std::string& scene_name, const Scene& scene,
                       const std::string& texture, const std::string& pattern,
                       const RenderSettings& settings, const RenderResult& result);

// `aapat diff`: reference, test, width, height, ppd, then rmse, psnr,
// ssim, flip (the mean), flip_min, flip_max, flip_weighted_q1,
// flip_weighted_median, flip_weighted_q3 and flip_histogram (pixels per
// bucket of 1/100). `reference` and `test` name the images ("" leaves them
// out: Python's arrays).
JsonObject diff_json(const std::string& reference, const std::string& test, const ImageDiff& diff);

}  // namespace aapat
