// The explorer page's face of the library (embind): each function takes and
// returns JSON text, built by the same library functions the CLI's --json and
// Python use (eval_json, optimize_run_json, discrepancy_json,
// temporal_report_json, registry_json, export_pattern), so the page shows
// the same numbers under the same names. An Error becomes {"error": message},
// which the page shows; nothing is thrown into JavaScript.
#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/json_depth.h"
#include "aapat/core/lattice.h"
#include "aapat/core/metric_simd.h"
#include "aapat/core/objective.h"
#include "aapat/core/pattern_edit.h"
#include "aapat/core/text.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/aapat_catalog.h"
#include "aapat/io/api_export.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/registry/page_limits.h"
#include "aapat/registry/spec_registries.h"
#include "aapat/render/scene.h"
#include "aapat/study/eval_study.h"
#include "aapat/study/optimize_run.h"
#include "aapat/study/perceptual_objective.h"
#include "aapat/study/point_set_study.h"
#include "aapat/study/render_study.h"
#include "aapat/study/study_json.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/accumulation.h"
#include "aapat/temporal/model/model_json.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "aapat/version.h"

namespace aapat::web {
namespace {

using Json = nlohmann::json;

std::string answer(const std::function<JsonObject()>& work) {
  try {
    return json_text(work());
  } catch (const std::exception& e) {
    return json_text(JsonObject{{"error", e.what()}});
  }
}

Json parse_request(const std::string& text) {
  check_json_depth(text, "request");  // a link nested thousands deep, before the parser recurses
  Json j = Json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) throw Error("request: not a JSON object");
  return j;
}

template <typename T>
T field(const Json& j, const char* key, T fallback) {
  if (!j.contains(key) || j[key].is_null()) return fallback;
  try {
    return j[key].get<T>();
  } catch (const Json::exception&) {
    throw Error(fmt::format("{}: not the expected type", key));
  }
}

double finite_field(const Json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number())
    throw Error(fmt::format("{}: expected a number", key));
  const double v = j[key].get<double>();
  if (!std::isfinite(v)) throw Error(fmt::format("{}: not a finite number", key));
  return v;
}

int int_field(const Json& j, const char* key, int fallback, int lo, int hi) {
  if (!j.contains(key) || j[key].is_null()) return fallback;
  if (!j[key].is_number()) throw Error(fmt::format("{}: expected a number", key));
  const double v = j[key].get<double>();
  if (!(v >= lo && v <= hi) || v != std::floor(v))
    throw Error(fmt::format("{}: {} is not a whole number in {}..{}", key, v, lo, hi));
  return static_cast<int>(v);
}

// The pattern a request carries: its "pattern" member, a pattern file's JSON
// (checked as a file is), or a catalog name.
Pattern pattern_of(const Json& request, const char* key = "pattern") {
  if (!request.contains(key)) throw Error(fmt::format("{}: missing", key));
  const Json& v = request[key];
  if (v.is_string()) {
    return named_pattern(v.get<std::string>());  // the CLI's message for a name it lacks
  }
  return pattern_from_json(v.dump(), key);
}

JsonObject pattern_doc(const Pattern& p) {
  return JsonObject::parse(pattern_to_json(p));
}

Objective objective_of_request(const Json& request) {
  return parse_objective(field<std::string>(request, "objective", std::string(kDefaultObjective)),
                         "objective");
}

// ---------------------------------------------------------------------------

std::string info() {
  return answer([] {
    JsonObject objectives = JsonObject::array();
    for (const NamedObjective& n : objective_registry())
      objectives.push_back({{"name", n.info.name},
                            {"summary", n.info.summary},
                            {"components", n.objective.components()}});
    JsonObject motions = JsonObject::array();
    for (const ComparisonMotion& m : kComparisonMotions)
      motions.push_back({{"name", m.name}, {"summary", m.summary}});
    return JsonObject{{"version", AAPAT_VERSION},
                      {"simd", simd_target()},
                      {"comparison_motions", motions},
                      {"default_objective", kDefaultObjective},
                      {"objectives", objectives},
                      {"lattice_steps", kLatticeSteps},
                      {"border_snap", kBorderSnap},
                      {"limits",
                       {{"view_size", kMaxPageViewSize},
                        {"points", kMaxPagePoints},
                        {"spectrum_size", kMaxPageSpectrumSize},
                        {"starts", kMaxPageStarts},
                        {"link_bytes", kMaxPageLinkBytes}}},
                      {"registry", registry_json()}};
  });
}

// A link's objective and scene read by the library's parsers, so that the
// page sets its controls from the same reading as every other face:
// {objective?, scene?} -> {objective: objective_json, scene_name, and a
// half-plane's angle and offset}.
std::string read_link(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    JsonObject out = JsonObject::object();
    if (r.contains("objective")) out["objective"] = objective_json(objective_of_request(r));
    if (r.contains("scene")) {
      const std::string spec = field<std::string>(r, "scene", "");
      const Scene scene = make_scene(spec, 8, 8);  // the library's parser: any fault named
      out["scene_name"] = std::string(split(spec, ':')[0]);
      if (const auto* h = std::get_if<HalfPlaneScene>(&scene.shape)) {
        out["angle"] = h->angle_deg;
        out["offset"] = h->offset;
      }
    }
    return out;
  });
}

// {pattern}: a catalog pattern, or a pattern file's text checked as `aapat` checks a file.
std::string load_pattern(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    if (r.contains("text"))
      return JsonObject{{"pattern", pattern_doc(pattern_from_json(
                                        field<std::string>(r, "text", ""),
                                        field<std::string>(r, "source", "uploaded file")))}};
    return JsonObject{{"pattern", pattern_doc(pattern_of(r, "name"))}};
  });
}

// `aapat eval --json`'s document for one pattern, the worst kernel's
// W(theta) E1(theta) for the polar plot, and the objective in words.
std::string evaluate(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const Objective o = objective_of_request(r);
    const Metric metric = o.metric();
    const Pattern p = pattern_of(r);
    const auto evaluations = evaluate_patterns(metric, {p}, false, true);
    return JsonObject{{"eval", eval_json(o, metric.angle_count(), {p}, evaluations)},
                      {"objective", objective_json(o)},  // the keys of every --json
                      {"caption", o.caption()},
                      {"angles_deg", metric.acuity().angles_deg},
                      {"acuity_weights", metric.acuity().weights},
                      {"profile", evaluations[0].worst_profile}};
  });
}

// The perceptual objective (study/perceptual_objective.h) of the pattern
// under `objective` (a perceptual spec): the document of `aapat eval
// --objective SPEC --json`. Each spec's charts and ideals are rendered once.
std::string perceptual(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const PerceptualSpec spec =
        parse_perceptual(field<std::string>(r, "objective", std::string(kPerceptualObjective)));
    const Pattern p = pattern_of(r);
    static std::map<std::string, std::unique_ptr<PerceptualObjective>> kept;
    auto& o = kept[spec.text()];
    if (!o) o = std::make_unique<PerceptualObjective>(spec);
    return perceptual_eval_json(spec, {p}, {o->evaluate(p)});
  });
}

std::string move(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const Pattern p = pattern_of(r);
    return JsonObject{
        {"pattern",
         pattern_doc(move_sample(p, int_field(r, "set", 0, 0, kMaxTileSide * kMaxTileSide),
                                 int_field(r, "index", 0, 0, static_cast<int>(kMaxSamplesPerSet)),
                                 {finite_field(r, "x"), finite_field(r, "y")},
                                 field<bool>(r, "lattice", false) ? kLatticeSteps : 0))}};
  });
}

std::string weight(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const Pattern p = pattern_of(r);
    const int kernel = int_field(r, "kernel", 0, 0, kMaxTileSide * kMaxTileSide);
    const int index = int_field(r, "index", 0, 0, static_cast<int>(kMaxPatternSamples));
    if (r.contains("value") && r["value"].is_string())
      throw Error(fmt::format("weight {} of kernel {}: '{}' is not a number", index, kernel,
                              r["value"].get<std::string>()));
    const double value = r.contains("value") && r["value"].is_number()
                             ? r["value"].get<double>()
                             : std::numeric_limits<double>::quiet_NaN();
    return JsonObject{{"pattern", pattern_doc(set_weight(p, kernel, index, value))}};
  });
}

// The pattern file's text, byte for byte what `aapat show PATTERN -o FILE.json` writes.
std::string pattern_file(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    return JsonObject{{"text", pattern_to_json(pattern_of(r))}};
  });
}

std::string snap(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    return JsonObject{{"pattern", pattern_doc(snap_to_lattice(pattern_of(r), kLatticeSteps))}};
  });
}

// The text `aapat export PATTERN --api API [--shader S] [--snap]` writes.
std::string export_text(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const ApiProfile& profile = api_profile(field<std::string>(r, "api", "d3d12-tier1"));
    const std::string shader = field<std::string>(r, "shader", "");
    return JsonObject{{"text", export_pattern(pattern_of(r), profile, objective_of_request(r),
                                              shader.empty() ? default_shader(profile)
                                                             : parse_shader_language(shader),
                                              field<bool>(r, "snap", false))}};
  });
}

// `aapat optimize --json`: a family searched or a pattern polished, with
// progress(done, total, note) as starts finish.
std::string optimize(const std::string& request, emscripten::val progress) {
  return answer([&] {
    const Json r = parse_request(request);
    OptimizeRunSettings s;
    s.family = field<std::string>(r, "family", "");
    if (r.contains("pattern")) {
      s.start = pattern_of(r);
      s.start_label = s.start->name;
    }
    check_family_or_pattern(!s.family.empty(), s.start.has_value());
    s.placement = field<std::string>(r, "placement", "");
    if (r.contains("starts")) s.starts = int_field(r, "starts", 1, 1, kMaxPageStarts);
    s.seed = static_cast<uint64_t>(int_field(r, "seed", 1, 0, kMaxPageSeed));
    s.seeds = field<std::string>(r, "seeds", s.seeds);
    s.optimizer.method =
        parse_method(field<std::string>(r, "method", method_key(s.optimizer.method)));
    s.optimizer.max_iterations =
        int_field(r, "iterations", s.optimizer.max_iterations, 1, kMaxPageIterations);
    s.optimizer.weights_only = field<bool>(r, "weights_only", false);
    s.lattice = field<bool>(r, "lattice", false) ? kLatticeSteps : 0;
    s.api = field<std::string>(r, "api", "");
    s.strictly_inside = !field<bool>(r, "border_samples", false);
    const bool report = !progress.isUndefined() && !progress.isNull();
    const OptimizeRunResult result =
        optimize_run(objective_of_request(r), s, [&](int done, int total, const std::string& note) {
          if (report) progress(done, total, note);
        });
    return JsonObject{{"report", optimize_run_json(result)}, {"pattern", pattern_doc(result.best)}};
  });
}

// The small rendered view: the pattern tiled over a scene, its reference
// (kept per scene and size: a drag re-renders only the pattern) and the
// figures `aapat render --json` reports.
std::string render(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const int size = int_field(r, "size", 64, 8, kMaxPageViewSize);
    const std::string spec = field<std::string>(r, "scene", "zoneplate");
    RenderSettings s;
    s.width = s.height = size;
    s.sampling.pattern = pattern_of(r);
    s.measure = true;
    s.reference.samples =
        int_field(r, "reference_samples", s.reference.samples, 1, kMaxPageReferenceSamples);
    s.reference.seed = reference_seed(s.sampling.seed);
    const Scene scene = make_scene(spec, size, size);
    static std::map<std::string, Image> kept;
    const ReferenceSource cached = [&](const Scene& sc, int w, int h, const ReferenceSettings& rs,
                                       double offset) {
      const std::string key = fmt::format("{} {}x{} {} {} {} {}", canonical_text(sc), w, h,
                                          rs.samples, rs.filter, rs.seed, offset);
      auto it = kept.find(key);
      if (it == kept.end()) {
        if (kept.size() > 16) kept.clear();
        it = kept.emplace(key, render_reference(sc, w, h, rs, offset)).first;
      }
      return it->second;
    };
    const RenderResult result = render_study(scene, s, cached);
    JsonObject doc{{"scene", canonical_text(scene)},
                   {"width", size},
                   {"height", size},
                   {"reference", describe_reference(s.reference)}};
    doc.update(figures_json(*result.figures));  // the figures of `aapat render --json`
    doc["image"] = result.image.values;
    doc["reference_image"] = result.reference->values;
    return doc;
  });
}

// A point set: the points, its power spectrum with the radial average, and
// `aapat discrepancy --json`'s document.
std::string points(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const std::string spec = field<std::string>(r, "generator", "jittered");
    const int n = int_field(r, "n", 256, 1, kMaxPagePoints);
    const uint64_t seed = static_cast<uint64_t>(int_field(r, "seed", 1, 0, kMaxPageSeed));
    const std::vector<Vec2> pts = generate_points(spec, n, seed);
    SpectrumSettings ss;
    ss.size = int_field(r, "spectrum_size", 64, 8, kMaxPageSpectrumSize);
    const SpectrumStudy st = spectrum_study([&](int) { return pts; }, ss);
    const DiscrepancyReport d =
        discrepancy_report(pts, parse_measures(field<std::string>(
                                    r, "measures", std::string(kDefaultDiscrepancyMeasures))));
    JsonObject xy = JsonObject::array();
    for (const Vec2& p : pts) xy.push_back({p.x, p.y});
    return JsonObject{{"points", xy},
                      {"spectrum", {{"size", st.mean.size}, {"power", st.mean.power}}},
                      {"radial", {{"radius", st.radial.radius}, {"power", st.radial.power}}},
                      {"discrepancy", discrepancy_json(spec, d)}};
  });
}

// A jitter sequence: its frames' samples and `aapat sequence eval --json`'s row.
std::string sequence(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    const Sequence s = resolve_sequence(field<std::string>(r, "sequence", "aapat-taa-8"));
    const Accumulation a = make_accumulation(
        field<std::string>(r, "model", std::string(kDefaultAccumulation)),
        field<double>(r, "alpha", kDefaultAlpha), int_field(r, "window", 0, 0, kMaxSequenceFrames),
        field<std::string>(r, "resolve", ""));
    const Metric metric = objective_of_request(r).metric();
    const TemporalReport report = evaluate_temporal(s, a, metric);
    JsonObject frames = JsonObject::array();
    for (const Pattern& frame : s.frames) {  // the base pixel's samples and weights
      JsonObject f = JsonObject::array();
      for (size_t i = 0; i < frame.sets[0].size(); ++i)
        f.push_back({frame.sets[0][i].x, frame.sets[0][i].y, frame.weights[0][i]});
      frames.push_back(f);
    }
    return JsonObject{{"frames", frames}, {"report", temporal_report_json(s, report)}};
  });
}

// Jitter sequences rendered through an engine's TAA preset on the same
// scenes, the first the baseline: `aapat sequence compare --json`'s
// document, built from the same settings (EngineComparison's defaults where
// the request is silent) and the same library calls. The references are
// rendered in the page (no disk cache), so a request keeps them small.
std::string engine_compare(const std::string& request) {
  return answer([&] {
    const Json r = parse_request(request);
    if (!r.contains("taa"))
      throw Error("taa: missing (an engine preset: " + engine_preset_names() + ")");
    const double ratio = r.contains("ratio") ? finite_field(r, "ratio") : 1.0;
    const EngineComparison defaults;
    EngineComparison c;
    c.taa = make_engine_taa(field<std::string>(r, "taa", ""), ratio, {});
    const int random_scenes = int_field(r, "random_scenes", 0, 0, kMaxComparisonScenes);
    c.seed = static_cast<uint64_t>(int_field(r, "seed", 1, 0, kMaxPageSeed));
    c.scenes =
        comparison_scenes(field<std::vector<std::string>>(r, "scenes", {}), random_scenes,
                          int_field(r, "shapes", kDefaultRandomSceneShapes, 0, 1 << 20), c.seed);
    c.motion = field<std::string>(r, "motion", defaults.motion);
    c.width = c.height = int_field(r, "size", defaults.width, 1, kMaxPageViewSize);
    c.frames = int_field(r, "frames", defaults.frames, 0, 1 << 20);
    c.warmup = int_field(r, "warmup", defaults.warmup, 0, 1 << 20);
    c.reference.samples =
        int_field(r, "reference_samples", defaults.reference.samples, 1, kMaxPageReferenceSamples);
    c.resamples = int_field(r, "resamples", defaults.resamples, 0, 1 << 20);
    if (r.contains("max_speed")) c.max_speed = finite_field(r, "max_speed");
    // Either every sequence ("sequences", the first the baseline), or one
    // ("sequence") against a baseline ("against"; by default the preset's own
    // jitter, as `aapat sequence search` takes it).
    std::vector<std::string> specs = field<std::vector<std::string>>(r, "sequences", {});
    if (r.contains("sequence")) {
      const std::string against = field<std::string>(r, "against", "");
      specs = {against.empty() ? c.taa.jitter : against, field<std::string>(r, "sequence", "")};
    }
    std::vector<Sequence> sequences;
    for (const std::string& spec : specs)
      sequences.push_back(resolve_sequence_for_ratio(spec, ratio, nullptr));
    validate(c, sequences.size());  // the library's checks, before any render
    return engine_comparison_json(c, compare_under_engine(sequences, c));
  });
}

}  // namespace
}  // namespace aapat::web

EMSCRIPTEN_BINDINGS(aapat_explorer) {
  using namespace aapat::web;
  emscripten::function("info", &info);
  emscripten::function("readLink", &read_link);
  emscripten::function("loadPattern", &load_pattern);
  emscripten::function("evaluate", &evaluate);
  emscripten::function("perceptual", &perceptual);
  emscripten::function("moveSample", &move);
  emscripten::function("setWeight", &weight);
  emscripten::function("patternFile", &pattern_file);
  emscripten::function("snap", &snap);
  emscripten::function("exportText", &export_text);
  emscripten::function("optimize", &optimize);
  emscripten::function("render", &render);
  emscripten::function("points", &points);
  emscripten::function("sequence", &sequence);
  emscripten::function("engineCompare", &engine_compare);
}
