// The papers' experiments re-run: Laine-Aila Table 3 and Figure 10,
// Hasselgren Table 2, the hardware lattice table.
#include <utility>
#include <variant>

#include "aapat/study/objective_study.h"
#include "aapat/study/optimize_run.h"
#include "aapat/study/refine_search.h"
#include "aapat/study/study_json.h"
#include "bindings.h"

namespace aapat::python {

void bind_studies(py::module_& m) {
  m.def(
      "study_compare",
      [](const std::vector<py::object>& patterns,
         const std::optional<std::vector<std::string>>& scenes,
         const std::variant<int, std::pair<int, int>>& size, int frames, int reference_samples,
         int resamples, uint64_t seed) {
        StudySettings s;
        if (scenes) s.scenes = *scenes;
        // N for N x N, or (width, height), as `--size` takes N or WxH.
        if (const int* n = std::get_if<int>(&size))
          s.width = s.height = *n;
        else
          std::tie(s.width, s.height) = std::get<std::pair<int, int>>(size);
        s.frames = frames;
        s.reference.samples = reference_samples;
        s.resamples = resamples;
        s.seed = seed;
        validate(s);
        std::vector<StudyPattern> list;
        for (const py::object& q : patterns) {
          const Pattern p = to_pattern(q);
          list.push_back(
              {py::isinstance<py::str>(q) ? q.cast<std::string>() : p.name, "", p, {}, {}, {}});
        }
        const auto measured = interruptible([&] {
          return measure_patterns(std::move(list), s, ReferenceSource(render_reference));
        });
        return to_python(study_compare_json(s, study_objectives(s), measured));
      },
      py::arg("patterns"), py::kw_only(), py::arg("scenes") = py::none(),
      py::arg("size") = std::pair<int, int>{StudySettings{}.width, StudySettings{}.height},
      py::arg("frames") = StudySettings{}.frames,
      py::arg("reference_samples") = StudySettings{}.reference.samples,
      py::arg("resamples") = StudySettings{}.resamples, py::arg("seed") = StudySettings{}.seed,
      R"doc(aapat study --compare: every objective and rendered measure of the patterns
(catalog names, files or aapat.Pattern; any family) on the study's scenes
(default its six), per scene, and each pattern after the first against the
first, paired over the scenes (scenes lower, mean difference with a bootstrap
interval, sign test). The document of `aapat study --compare --json`.)doc");

  m.def(
      "perceptual_eval",
      [](const py::object& patterns, const std::string& objective) {
        const PerceptualSpec spec = parse_perceptual(objective);
        std::vector<Pattern> list;
        if (py::isinstance<py::list>(patterns) || py::isinstance<py::tuple>(patterns)) {
          for (const py::handle& h : patterns) list.push_back(to_pattern(h));
        } else {
          list.push_back(to_pattern(patterns));
        }
        const auto errors = interruptible([&] {
          const PerceptualObjective o(spec);
          std::vector<PerceptualError> out;
          for (const Pattern& p : list) out.push_back(o.evaluate(p));
          return out;
        });
        return to_python(perceptual_eval_json(spec, list, errors));
      },
      py::arg("patterns"), py::kw_only(), py::arg("objective") = std::string(kPerceptualObjective),
      R"doc(The perceptual objective (FLIP on edge, line and dot charts; docs/perceptual.md)
of a pattern or a list of them (catalog names, files or aapat.Pattern; any
family): the document of `aapat eval --objective SPEC --json`, each row with
its family, n, value ("perceptual") and each kind's mean FLIP ("kinds").)doc");

  m.def(
      "refine",
      [](const py::object& pattern, const std::string& objective,
         const std::optional<std::vector<std::string>>& scenes,
         const std::variant<int, std::pair<int, int>>& size, const std::string& measure,
         int reference_samples, const std::string& api, int max_tries, double step, double min_step,
         int weight_steps) {
        const Pattern start = to_pattern(pattern);
        RefineSettings s;
        s.max_tries = max_tries;
        s.weight_steps = weight_steps;
        s.step = step;
        s.min_step = min_step;
        s.api = api;
        validate(s, start);  // before the objective's references are rendered
        std::optional<PerceptualSpec> spec;
        StudySettings study;
        if (scenes) {
          if (weight_steps > 0)
            throw ParameterError("weight_steps",
                                 ": a rendered measure over scenes has no weight gradient (the "
                                 "perceptual objective has)");
          study.scenes = *scenes;
          if (const int* n = std::get_if<int>(&size))
            study.width = study.height = *n;
          else
            std::tie(study.width, study.height) = std::get<std::pair<int, int>>(size);
          study.reference.samples = reference_samples;
        } else {
          spec = parse_perceptual(objective);
        }
        const auto [doc, refined] = interruptible([&] {
          std::optional<PerceptualObjective> perceptual;
          std::optional<RenderedObjective> rendered;
          RefineObjective o;
          if (spec) {
            o = refine_objective(perceptual.emplace(*spec));
          } else {
            rendered.emplace(study, ReferenceSource(render_reference), measure,
                             start.footprint.size != 1);
            o = refine_objective(*rendered);
          }
          const RefineResult r = refine_pattern(start, o, s);
          return std::pair{refine_json(o, start, s, r), r.pattern};
        });
        py::dict out = to_python(doc);
        out["refined"] = py::cast(refined);
        return out;
      },
      py::arg("pattern"), py::kw_only(), py::arg("objective") = std::string(kPerceptualObjective),
      py::arg("scenes") = py::none(), py::arg("size") = kRenderedObjectiveSize,
      py::arg("measure") = kRenderedObjectiveMeasure,
      py::arg("reference_samples") = StudySettings{}.reference.samples, py::arg("api") = "",
      py::arg("max_tries") = RefineSettings{}.max_tries, py::arg("step") = RefineSettings{}.step,
      py::arg("min_step") = RefineSettings{}.min_step,
      py::arg("weight_steps") = RefineSettings{}.weight_steps,
      R"doc(aapat refine: the pattern's positions and weights refined by a compass search,
never worse than the start, under the perceptual objective or, with `scenes`,
the mean rendered `measure` over them at `size` (as study_compare renders
them); with `api`, on that API's lattice; with `weight_steps`, then that many
gradient steps on the weights at most (the perceptual objective only).
Returns the document of `aapat refine --json` ({objective, pattern: the
start's name, family, api when given, before, after, tries; compass_after and
weight_steps with weight steps}) with `refined`, the aapat.Pattern named
START-perceptual or START-rendered.)doc");

  m.def(
      "table3",
      [](int patterns, int iterations, uint64_t seed, const std::string& method,
         const py::object& objective, const py::object& filter, const py::object& acuity,
         const py::object& norm) {
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Table3Settings s{patterns, iterations, seed, parse_method(method)};
        const auto rows = interruptible([&] { return table3(o.metric(), s); });
        return rows_of(table3_json(o, s, rows));
      },
      py::kw_only(), py::arg("patterns") = Table3Settings{}.patterns,
      py::arg("iterations") = Table3Settings{}.iterations, py::arg("seed") = Table3Settings{}.seed,
      py::arg("method") = method_key(Table3Settings{}.method),
      py::arg("objective") = std::string(kPapersObjective), py::arg("filter") = py::none(),
      py::arg("acuity") = py::none(), py::arg("norm") = py::none(),
      with_metric_args(
          R"doc(Laine-Aila Table 3: P(16,16,4) jittered and Poisson patterns, min/avg/max E2,
then the best optimized for weights (opt_w) and positions (opt_wp, with
`method`). The rows of `aapat table3 --json`: a list of dicts with the paper's
five numbers beside.)doc"));

  m.def(
      "figure10",
      [](int starts, uint64_t seed, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Figure10Settings s{starts, seed};
        const auto fig = interruptible([&] { return figure10(o.metric(), s); });
        return rows_of(figure10_json(o, s, fig));
      },
      py::kw_only(), py::arg("starts") = Figure10Settings{}.starts,
      py::arg("seed") = Figure10Settings{}.seed,
      py::arg("objective") = std::string(kPapersObjective), py::arg("filter") = py::none(),
      py::arg("acuity") = py::none(), py::arg("norm") = py::none(),
      with_metric_args(
          R"doc(Laine-Aila Figure 10: the best E2 of P(1,1,n), P(4,1+,n), P(1,4,n), P(4,4,n)
against n. The rows of `aapat figure10 --json`: a list of dicts {family, n, e2,
placement, series}.)doc"));

  m.def(
      "table2",
      [](int size, int frames) {
        AnimationSettings a;
        a.width = a.height = size;
        a.frames = frames;
        const auto rows = interruptible([&] { return table2(a); });
        return rows_of(table2_json(a, rows));
      },
      py::kw_only(), py::arg("size") = AnimationSettings{}.width,
      py::arg("frames") = AnimationSettings{}.frames,
      R"doc(Hasselgren Table 2 re-measured: E2, RMSE and max deviation of the nine patterns
on the translating circle (size x size, `frames` frames, 256-sample reference).
The rows of `aapat table2 --json`: {pattern, label, e2, rmse, max_deviation,
paper: {e2, rmse, max_deviation}}.)doc");

  m.def(
      "hardware_table",
      [](int starts, uint64_t seed, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        const Objective o = make_objective(objective, filter, acuity, norm);
        const HardwareTableSettings s{starts, seed};
        const auto rows = interruptible([&] { return hardware_table(o.metric(), s); });
        return rows_of(hardware_table_json(o, s, rows));
      },
      py::kw_only(), py::arg("starts") = HardwareTableSettings{}.starts,
      py::arg("seed") = HardwareTableSettings{}.seed, AAPAT_OBJECTIVE_ARGS,
      with_metric_args(
          R"doc(What the APIs' 1/16-pixel lattice costs: standard and optimized patterns at 2,
4, 8 and 16 samples, and the sharing schemes, continuous and on the lattice.
The rows of `aapat hardware-table --json`: {n, pattern, profile, layout,
e2_continuous, e2_lattice}.)doc"));
}

}  // namespace aapat::python
