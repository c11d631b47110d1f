#include "aapat/study/study_json.h"

#include "aapat/core/filter_catalog.h"
#include "aapat/render/mesh.h"
#include "aapat/study/optimize_run.h"

namespace aapat {

JsonObject table3_json(const Objective& objective, const Table3Settings& settings,
                       const std::vector<Table3Row>& rows) {
  JsonObject doc = json_report("table3");
  doc.update(JsonObject{{"family", "P(16,16,4)"},
                        {"patterns", settings.patterns},
                        {"seed", settings.seed},
                        {"method", method_key(settings.method)}});
  doc.update(objective_json(objective));
  JsonObject& out = doc["rows"] = JsonObject::array();
  for (const Table3Row& r : rows)
    out.push_back({{"distribution", r.distribution},
                   {"min", r.e2[0]},
                   {"avg", r.e2[1]},
                   {"max", r.e2[2]},
                   {"opt_w", r.e2[3]},
                   {"opt_wp", r.e2[4]},
                   {"paper", r.paper}});
  return doc;
}

JsonObject figure10_json(const Objective& objective, const Figure10Settings& settings,
                         const Figure10& figure) {
  JsonObject doc = json_report("figure10");
  doc.update(JsonObject{{"starts", settings.starts}, {"seed", settings.seed}});
  doc.update(objective_json(objective));
  JsonObject& out = doc["rows"] = JsonObject::array();
  for (const Figure10Point& p : figure.points)
    out.push_back({{"family", p.family},
                   {"n", p.n},
                   {"e2", p.e2},
                   {"placement", p.placement},
                   {"series", figure.series[static_cast<size_t>(p.series)]}});
  return doc;
}

JsonObject hardware_table_json(const Objective& objective, const HardwareTableSettings& settings,
                               const std::vector<HardwareTableRow>& rows) {
  JsonObject doc = json_report("hardware-table");
  doc.update(objective_json(objective));
  doc.update(JsonObject{{"starts", settings.starts}, {"seed", settings.seed}});
  JsonObject& out = doc["rows"] = JsonObject::array();
  for (const HardwareTableRow& r : rows)
    out.push_back({{"n", r.n},
                   {"pattern", r.pattern},
                   {"profile", r.profile},
                   {"layout", r.layout},
                   {"e2_continuous", r.continuous_e2},
                   {"e2_lattice", r.lattice_e2}});
  return doc;
}

JsonObject table2_json(const AnimationSettings& settings, const std::vector<Table2Row>& rows) {
  JsonObject doc = json_report("table2");
  doc.update(JsonObject{{"animation", settings.animation},
                        {"frames", settings.frames},
                        {"width", settings.width},
                        {"height", settings.height},
                        {"reference", describe_reference(settings.reference)}});
  doc.update(objective_json(named_objective(kPapersObjective)));
  JsonObject& out = doc["rows"] = JsonObject::array();
  for (const Table2Row& r : rows)
    out.push_back(
        {{"pattern", r.pattern},
         {"label", r.label},
         {"e2", r.e2},
         {"rmse", r.rmse},
         {"max_deviation", r.max_deviation},
         {"paper",
          {{"e2", r.paper_e2}, {"rmse", r.paper_rmse}, {"max_deviation", r.paper_max_deviation}}}});
  return doc;
}

JsonObject enumeration_json(const Objective& objective, const EnumerationSettings& settings,
                            const Enumeration& enumeration) {
  JsonObject doc = json_report("enumerate");
  doc.update(JsonObject{{"family", "P(4,1+,n)"},
                        {"max_per_edge", settings.rules.max_per_edge},
                        {"cull_one_edge", settings.rules.cull_one_edge},
                        {"optimized", settings.optimize},
                        {"starts", settings.optimize ? JsonObject(settings.starts) : JsonObject()},
                        {"seed", settings.seed}});
  doc.update(objective_json(objective));
  JsonObject& out = doc["rows"] = JsonObject::array();
  for (const EnumerationRow& r : enumeration.rows)
    out.push_back({{"id", r.id},
                   {"n", r.n},
                   {"placement", r.config.sites()},
                   {"samples_read", r.config.samples()},
                   {"e2", settings.optimize ? JsonObject(r.e2) : JsonObject()}});
  return doc;
}

JsonObject snap_json(const Objective& objective, const std::string& pattern, int lattice,
                     const SnapResult& result) {
  JsonObject doc = json_report("snap");
  doc.update(JsonObject{{"pattern", pattern}, {"lattice", lattice}});
  doc.update(objective_json(objective));
  doc.update(JsonObject{{"e2_before", result.e2_before},
                        {"e2_snapped", result.e2_snapped},
                        {"largest_move", result.largest_move},
                        {"family", family(result.snapped)},
                        {"n", samples_per_pixel(result.snapped)}});
  if (result.e2_optimized_weights) doc["e2_optimized_weights"] = *result.e2_optimized_weights;
  return doc;
}

JsonObject discrepancy_json(const std::string& source, const DiscrepancyReport& d) {
  JsonObject doc = json_report("discrepancy");
  if (!source.empty()) doc["source"] = source;
  doc["points"] = d.points;
  for (const L2Value& v : d.l2) doc[std::string(l2_kind_info(v.kind).key)] = v.value;
  if (d.star)
    doc.update(JsonObject{{"star_lower", d.star->lower},
                          {"star_upper", d.star->upper},
                          // The exact value where it was computed, else null; the flag beside it.
                          {"star_exact", d.star->exact ? JsonObject(d.star->upper) : nullptr},
                          {"star_is_exact", d.star->exact},
                          {"star_gap", d.star->upper - d.star->lower}});
  if (d.edge)
    doc.update(JsonObject{{"edge", d.edge->value}, {"edge_normal_deg", d.edge->normal_deg}});
  return doc;
}

JsonObject shading_json(const Sampling& s, const RenderStats& stats) {
  return {{"mode", shading_mode_name(s.shading.mode)},
          {"shading_point", shading_point_name(s.shading.point)},
          {"texture_filter", s.shading.texture.name},
          {"lookups_per_pixel", stats.lookups_per_pixel},
          {"shadings_per_pixel", stats.shadings_per_pixel}};
}

JsonObject adaptive_json(const AdaptiveSettings& a, const AdaptiveImage& r) {
  return {{"criterion", refinement_criterion_name(a.criterion)},
          {"threshold", a.threshold},
          {"max_depth", a.max_depth},
          {"max_samples", a.max_samples},
          {"per_square", a.per_square},
          {"average_samples", r.average_samples},
          {"refined_fraction", r.refined_fraction},
          {"evaluations", r.evaluations}};
}

JsonObject grid_cell_json(const RenderGridCell& c) {
  JsonObject cell = c.sampling.pattern ? JsonObject{{"pattern", c.row}}
                                       : JsonObject{{"generator", c.sampling.generator},
                                                    {"samples", c.sampling.samples}};
  cell.update(JsonObject{{"filter", c.column}, {"samples_per_pixel", c.stats.samples_per_pixel}});
  cell.update(shading_json(c.sampling, c.stats));
  if (c.adaptive) {
    RenderOptions options;
    split_options(c.row, options);
    split_options(c.column, options);
    cell["adaptive"] = adaptive_json(*options.adaptive_settings(c.sampling), *c.adaptive);
  }
  cell.update(figures_json(c.figures));
  return cell;
}

JsonObject render_grid_json(const std::string& scene_name, const std::string& texture, int width,
                            int height, const ReferenceSettings& reference,
                            const std::vector<RenderGridCell>& cells) {
  JsonObject rows = JsonObject::array();
  for (const RenderGridCell& c : cells)
    if (!c.show_map) rows.push_back(grid_cell_json(c));
  JsonObject doc = json_report("render");
  doc.update(JsonObject{{"scene", scene_name},
                        {"texture", texture.empty() ? JsonObject() : JsonObject(texture)},
                        {"width", width},
                        {"height", height},
                        {"reference", describe_reference(reference)},
                        {"rows", rows}});
  return doc;
}

JsonObject study_compare_json(const StudySettings& settings,
                              const std::vector<StudyObjective>& objectives,
                              const std::vector<StudyPattern>& patterns) {
  JsonObject rows = JsonObject::array();
  for (const StudyPattern& p : patterns) {
    JsonObject measures = JsonObject::array();
    for (const auto& m : p.measures) measures.push_back(m);
    rows.push_back({{"pattern", p.name}, {"objectives", p.objective}, {"measures", measures}});
  }
  JsonObject names = JsonObject::array();
  for (const StudyObjective& ob : objectives) names.push_back(ob.name());
  JsonObject against = JsonObject::array();
  const std::vector<MeasureComparisons> c = compare_with_first(patterns, settings);
  for (size_t k = 0; k < c.size(); ++k) {
    JsonObject entry{{"pattern", patterns[k + 1].name}, {"against", patterns[0].name}};
    for (size_t q = 0; q < kStudyMeasures.size(); ++q)
      entry[kStudyMeasures[q]] = paired_comparison_json(c[k][q]);
    against.push_back(entry);
  }
  JsonObject doc = json_report("study");
  // The size and reference every rendered number depends on, in every result.
  doc.update(JsonObject{{"objectives", names},
                        {"scenes", settings.scenes},
                        {"measures", kStudyMeasures},
                        {"width", settings.width},
                        {"height", settings.height},
                        {"frames", settings.frames},
                        {"seed", settings.seed},
                        {"reference", describe_reference(settings.reference)},
                        {"patterns", rows},
                        {"against_first", against}});
  return doc;
}

JsonObject line_spectra_json(const std::vector<std::string>& kinds, uint64_t seed, int frequencies,
                             double max_frequency, const std::vector<LineSpectrum>& spectra) {
  JsonObject doc = json_report("spectrum");
  doc.update(JsonObject{{"dimensions", 1},
                        {"kinds", kinds},
                        {"points", spectra.back().points},
                        {"seed", seed},
                        {"frequencies", frequencies},
                        {"max_frequency", max_frequency}});
  const std::vector<double> f = line_frequencies(frequencies, max_frequency);
  JsonObject rows = JsonObject::array();
  for (int k = 0; k < frequencies; ++k) {
    JsonObject row{{"frequency", f[static_cast<size_t>(k)]}};
    for (const auto& sp : spectra) row[sp.kind] = sp.power[static_cast<size_t>(k)];
    rows.push_back(std::move(row));
  }
  doc["rows"] = std::move(rows);
  return doc;
}

JsonObject figures_json(const RenderFigures& f) {
  return {{"rmse", f.error.rmse},
          {"max_deviation", f.error.max_deviation},
          {"ssim", f.ssim ? JsonObject(*f.ssim) : nullptr},
          {"flip", f.flip}};
}

JsonObject render_json(const std::string& scene_name, const Scene& scene,
                       const std::string& texture, const std::string& pattern,
                       const RenderSettings& s, const RenderResult& r) {
  JsonObject doc = json_report("render");
  doc.update(JsonObject{{"scene", scene_name},
                        {"texture", texture.empty() ? JsonObject() : JsonObject(texture)},
                        {"width", s.width},
                        {"height", s.height},
                        {"channels", r.image.channels}});
  if (const auto* mesh = std::get_if<MeshScene>(&scene.shape)) {
    const Mesh& m = mesh->view->mesh();
    size_t textured = 0;
    for (const MeshMaterial& mat : m.materials) textured += mat.texture[0] != nullptr;
    JsonObject warnings = JsonObject::array();
    for (const std::string& w : m.warnings) warnings.push_back(w);
    doc["model"] = JsonObject{{"file", m.name},
                              {"triangles", m.triangles.size()},
                              {"vertices", m.positions.size()},
                              {"materials", m.materials.size()},
                              {"textured_materials", textured},
                              {"warnings", warnings}};
  }
  if (s.sampling.pattern)
    doc["pattern"] = pattern;
  else
    doc.update(JsonObject{{"generator", s.sampling.generator}, {"samples", s.sampling.samples}});
  doc.update(JsonObject{{"filter", s.filter ? s.filter->name() : "pattern weights"},
                        {"samples_per_pixel", r.stats.samples_per_pixel}});
  doc.update(shading_json(s.sampling, r.stats));
  if (r.adaptive) doc["adaptive"] = adaptive_json(*s.adaptive, *r.adaptive);
  if (r.figures) {
    doc["reference"] = describe_reference(s.reference);
    doc.update(figures_json(*r.figures));
  }
  return doc;
}

JsonObject diff_json(const std::string& reference, const std::string& test, const ImageDiff& d) {
  JsonObject doc = json_report("diff");
  if (!reference.empty()) doc["reference"] = reference;
  if (!test.empty()) doc["test"] = test;
  doc.update(JsonObject{{"width", d.flip.width}, {"height", d.flip.height}, {"ppd", d.ppd}});
  doc.update(JsonObject{{"rmse", d.rmse},
                        {"psnr", d.psnr ? JsonObject(*d.psnr) : nullptr},
                        {"ssim", d.ssim ? JsonObject(*d.ssim) : nullptr},
                        {"flip", d.flip.mean},
                        {"flip_min", d.flip.min},
                        {"flip_max", d.flip.max},
                        {"flip_weighted_q1", d.flip.weighted_q1},
                        {"flip_weighted_median", d.flip.weighted_median},
                        {"flip_weighted_q3", d.flip.weighted_q3},
                        {"flip_histogram", d.flip.histogram}});
  return doc;
}

}  // namespace aapat
