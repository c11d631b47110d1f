// Sequences over time: generate or load, evaluate under an accumulation
// model, optimize (docs/temporal.md).
#include <fmt/format.h>

#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/engine/engine_pans.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/model_json.h"
#include "aapat/temporal/model/pan_distribution.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/search/pan_search.h"
#include "aapat/temporal/search/rendered_search.h"
#include "aapat/temporal/search/search_json.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "bindings.h"

namespace aapat::python {
namespace {

// (frames, samples per frame, 2) for equal-sized frames of one pixel.
Array offsets_of(const Sequence& s) {
  const size_t k = s.frames.size(), n = s.frames[0].sets[0].size();
  Array out({k, n, size_t{2}});
  auto view = out.mutable_unchecked<3>();
  for (size_t f = 0; f < k; ++f) {
    if (s.frames[f].sets[0].size() != n)
      throw Error("sequence " + s.name + ": frames of different sizes have no offsets array");
    for (size_t i = 0; i < n; ++i) {
      view(f, i, 0) = s.frames[f].sets[0][i].x;
      view(f, i, 1) = s.frames[f].sets[0][i].y;
    }
  }
  return out;
}

constexpr const char* kModelArgs = R"doc(
    model: "ema" (default; history weight 1 - alpha) or "box" (the last `window` frames).
    alpha: the EMA's blend factor, in (0, 1]; default 0.1.
    window: the box's frames (0: the period).
    resolve: a filter spec each frame is resolved with over its neighbours' samples
        (e.g. "gaussian:sigma=0.47,radius=1.5"); "" for none.)doc";

}  // namespace

// The rendered commands' shared settings, as keyword arguments (the CLI's
// ComparisonOptions).
EngineComparison comparison_of(const std::string& taa, double ratio, const py::dict& settings,
                               const std::optional<std::vector<std::string>>& scenes,
                               int random_scenes, int shapes, const std::string& motion,
                               uint64_t seed, double max_speed, std::pair<int, int> size,
                               int frames, int warmup, int reference_samples,
                               const std::string& reference_filter) {
  EngineComparison c;
  c.taa = make_engine_taa(taa, ratio, taa_overrides_of(settings));
  c.scenes =
      comparison_scenes(scenes.value_or(std::vector<std::string>{}), random_scenes, shapes, seed);
  c.motion = motion;
  std::tie(c.width, c.height) = size;
  c.frames = frames;
  c.warmup = warmup;
  c.reference.samples = reference_samples;
  c.reference.filter = reference_filter;
  c.seed = seed;
  c.max_speed = max_speed;
  return c;
}

Sequence sequence_arg(const py::object& q, double ratio) {
  return py::isinstance<Sequence>(q)
             ? q.cast<Sequence>()
             : resolve_sequence_for_ratio(q.cast<std::string>(), ratio, nullptr);
}

void bind_temporal(py::module_& m) {
  py::class_<Sequence>(m, "Sequence", "K frame patterns used in turn (docs/temporal.md).")
      .def_readonly("name", &Sequence::name)
      .def_readonly("description", &Sequence::description)
      .def_property_readonly("period", &Sequence::period)
      .def_property_readonly(
          "frames", [](const Sequence& s) { return s.frames; },
          "The frames as aapat.Pattern objects.")
      .def_property_readonly("offsets", &offsets_of,
                             "(frames, samples per frame, 2): pixels from the pixel centre, y up.")
      .def("to_json", &sequence_to_json, "The sequence file's text (round-trips exactly).")
      .def("save", [](const Sequence& s, const std::string& path) { save_sequence_file(s, path); })
      .def("__repr__", [](const Sequence& s) {
        return "<aapat.Sequence " + s.name + ", " + std::to_string(s.period()) + " frames>";
      });

  m.def(
      "sequence",
      [](const std::string& spec, const py::object& pattern) {
        std::optional<Pattern> p;
        if (!pattern.is_none()) p = to_pattern(pattern);
        return resolve_sequence(spec, p);
      },
      py::arg("spec"), py::arg("pattern") = py::none(),
      R"doc(A sequence: a generator spec ("halton:frames=8", "r2:frames=16",
"sobol:frames=16,seed=1", "random:frames=16,seed=1", "display-lattice:ratio=1.5",
"msaa-alternating:samples=2,frames=2", "split:frames=K" with pattern=...; `aapat list`
has them all), a name of the optimized ones ("aapat-taa-8") or a file.)doc");

  m.def(
      "sequence_eval",
      [](const py::object& seq, const std::string& model, double alpha, int window,
         const std::string& resolve, double ratio, const py::object& objective,
         const py::object& filter, const py::object& acuity, const py::object& norm) {
        const Sequence s = py::isinstance<Sequence>(seq)
                               ? seq.cast<Sequence>()
                               : resolve_sequence(seq.cast<std::string>());
        const Metric metric = make_metric(objective, filter, acuity, norm);
        const Accumulation a = make_accumulation(model, alpha, window, resolve);
        const std::optional<Upscale> upscale =
            ratio != 1 ? std::optional(make_upscale(ratio)) : std::nullopt;
        const auto r = interruptible([&] { return evaluate_temporal(s, a, metric, 0, upscale); });
        return to_python(temporal_report_json(s, r));
      },
      py::arg("sequence"), py::kw_only(), py::arg("model") = std::string(kDefaultAccumulation),
      py::arg("alpha") = kDefaultAlpha, py::arg("window") = 0, py::arg("resolve") = "",
      py::arg("ratio") = 1.0, AAPAT_OBJECTIVE_ARGS,
      with_metric_args(
          (std::string(R"doc(The temporal metrics of a sequence (a Sequence or a spec) under an
accumulation model (at a render scale 1/ratio, each frame reconstructed into
display pixels, when ratio > 1, as `aapat sequence eval --ratio`): a dict with the keys of one row of `aapat sequence eval
--json`: sequence, frames, family, worst_e2, mean_e2, steady_e2, cut_curve,
settle_frame, flicker (the mean over the period's transitions), worst_flicker
(the largest), flicker_per_transition, mean_offset, worst_centroid, prefixes.)doc") +
           kModelArgs)
              .c_str()));

  m.def(
      "optimize_sequence",
      [](int frames, int samples_per_frame, double flicker_weight, double jitter_bound,
         const py::object& jitter_radius, const std::string& measure, int starts, uint64_t seed,
         int iterations, bool equal_weights, const std::string& api, const std::string& model,
         double alpha, int window, const py::object& ratio, const std::string& reconstruct,
         const py::object& progress, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        SequenceSearch s;
        if (ratio.is_none() && reconstruct != kDefaultReconstruction)
          throw Error("reconstruct: the reconstruction of an upscale; give ratio=R with it");
        if (!ratio.is_none()) s.upscale = make_upscale(ratio.cast<double>(), reconstruct);
        s.frames = frames;
        s.samples_per_frame = samples_per_frame;
        s.flicker_weight = flicker_weight;
        s.jitter_bound = jitter_bound;
        if (!jitter_radius.is_none()) s.jitter_radius = jitter_radius.cast<double>();
        s.frame_measure = parse_frame_measure(measure);
        s.starts = starts;
        s.seed = seed;
        s.iterations = iterations;
        s.optimize_weights = !equal_weights;
        if (!api.empty()) s.profile = &api_profile(api);
        s.model = make_accumulation(model, alpha, window, "");
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Metric metric = o.metric();
        const auto report = progress_of(progress);
        const auto r = interruptible([&] { return optimize_sequence(s, metric, report); });
        py::dict d = to_python(sequence_search_json(s, accumulation_text(s.model), o, r));
        d["result"] = r.best;
        return d;
      },
      py::kw_only(), py::arg("frames") = SequenceSearch{}.frames,
      py::arg("samples_per_frame") = SequenceSearch{}.samples_per_frame,
      py::arg("flicker_weight") = SequenceSearch{}.flicker_weight,
      py::arg("jitter_bound") = SequenceSearch{}.jitter_bound,
      py::arg("jitter_radius") = py::none(),
      py::arg("measure") = std::string(frame_measure_name(SequenceSearch{}.frame_measure)),
      py::arg("starts") = SequenceSearch{}.starts, py::arg("seed") = SequenceSearch{}.seed,
      py::arg("iterations") = SequenceSearch{}.iterations, py::arg("equal_weights") = false,
      py::arg("api") = "", py::arg("model") = std::string(kDefaultAccumulation),
      py::arg("alpha") = kDefaultAlpha, py::arg("window") = 0, py::arg("ratio") = py::none(),
      py::arg("reconstruct") = std::string(kDefaultReconstruction),
      py::arg("progress") = py::none(), AAPAT_OBJECTIVE_ARGS,
      R"doc(aapat optimize --sequence: the positions of every frame's samples minimizing
worst (or mean) steady E2 + flicker_weight x flicker under the model. The same
sequence as the command line for the same settings and seed. A dict with the
keys of `aapat optimize --sequence --json` (j, worst_e2, mean_e2, flicker,
halton_j, ...), its "result" the aapat.Sequence found. ratio: optimize the
jitter of an upscale (`--ratio`), each display pixel reconstructed by
`reconstruct` from the render pixels around it. progress: a callable
f(done, total, note), called as starts finish ("best J ..."), or None.)doc");

  m.def(
      "optimize_sequence_pan",
      [](int frames, const std::string& taa, double ratio, const py::dict& settings,
         const std::optional<std::vector<std::pair<double, double>>>& velocities,
         const py::object& start, double step, double min_step, double jitter_bound,
         const py::object& progress, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        PanSequenceSearch s;
        s.taa = make_engine_taa(taa, ratio, taa_overrides_of(settings));
        if (velocities)
          for (const auto& [dx, dy] : *velocities) s.velocities.push_back({dx, dy});
        s.start = py::isinstance<Sequence>(start)
                      ? start.cast<Sequence>()
                      : pan_search_start(frames, start.is_none() ? "" : start.cast<std::string>());
        s.step = step;
        s.min_step = min_step;
        s.jitter_bound = jitter_bound;
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Metric metric = o.metric();
        const auto report = progress_of(progress);
        const auto r = interruptible([&] { return search_sequence_under_pans(s, metric, report); });
        py::dict d = to_python(pan_search_json(s, o, r));
        d["result"] = r.best;
        return d;
      },
      py::kw_only(), py::arg("frames"), py::arg("taa"), py::arg("ratio") = 1.0,
      py::arg("settings") = py::dict(), py::arg("velocities") = py::none(),
      py::arg("start") = py::none(), py::arg("step") = PanSequenceSearch{}.step,
      py::arg("min_step") = PanSequenceSearch{}.min_step,
      py::arg("jitter_bound") = PanSequenceSearch{}.jitter_bound, py::arg("progress") = py::none(),
      AAPAT_OBJECTIVE_ARGS,
      with_metric_args(R"doc(aapat optimize --sequence K --taa PRESET: a jitter of `frames` frames
searched under motion, minimizing the pan model's steady mean E2 averaged over
the velocities ((dx, dy) display pixels per frame; default the command line's,
still among them) under an engine preset (settings: overrides by key) at
ratio, by a compass search from `start` (a Sequence or spec; default
Halton(2,3) from index 1) with steps from `step` halving to `min_step`
(docs/temporal.md, "Under motion"). The same sequence as the command line for
the same settings. A dict with the keys of its --json (start_mean_e2, mean_e2,
velocities [{velocity, start_mean_e2, mean_e2}], tries, kept, ...), its
"result" the aapat.Sequence found. progress: a callable f(done, total, note)
called as each step size finishes, or None.)doc"));

  m.def(
      "sequence_pan",
      [](const std::vector<py::object>& sequences, const std::string& taa, double ratio,
         const py::dict& settings,
         const std::optional<std::vector<std::pair<double, double>>>& velocities,
         int random_velocities, double max_speed, uint64_t seed, const py::object& progress,
         const py::object& objective, const py::object& filter, const py::object& acuity,
         const py::object& norm) {
        const EngineTaa t = make_engine_taa(taa, ratio, taa_overrides_of(settings));
        std::vector<Sequence> seqs;
        for (const py::object& q : sequences)
          seqs.push_back(py::isinstance<Sequence>(q)
                             ? q.cast<Sequence>()
                             : resolve_sequence_for_ratio(q.cast<std::string>(), ratio, nullptr));
        std::optional<std::vector<Vec2>> given;
        if (velocities) {
          given.emplace();
          for (const auto& [dx, dy] : *velocities) given->push_back({dx, dy});
        }
        const std::vector<Vec2> vs = pan_velocities(given, random_velocities, max_speed, seed);
        const Metric metric = make_metric(objective, filter, acuity, norm);
        const auto report = progress_of(progress);
        const auto rows = interruptible([&] { return evaluate_pans(seqs, t, vs, metric, report); });
        return to_python(JsonObject(pan_rows_json(rows))).cast<py::list>();
      },
      py::arg("sequences"), py::kw_only(), py::arg("taa"), py::arg("ratio") = 1.0,
      py::arg("settings") = py::dict(), py::arg("velocities") = py::none(),
      py::arg("random_velocities") = 0, py::arg("max_speed") = kDefaultRandomPanSpeed,
      py::arg("seed") = 1, py::arg("progress") = py::none(), AAPAT_OBJECTIVE_ARGS,
      with_metric_args(R"doc(aapat sequence pan: the steady mean E2 and flicker of each sequence (a
Sequence or a spec; a generator without frames= takes the upscaler's phases
for ratio) under an engine preset's reconstruction, history sampler and blend
(settings: overrides by key, as engine_taa's; rectification is not in the model)
while the scene pans at each velocity ((dx, dy) display pixels per frame;
(0, 0): still; default the command line's) and at random_velocities more
(each component uniform in +-max_speed from seed, as --random-velocities;
without velocities, instead of the defaults), by the linear model before
rectification (docs/temporal.md). A list with one dict per sequence, the rows
of `aapat sequence pan --json`: sequence, phases, mean_e2, flicker (the means
over the velocities), velocities [{velocity, mean_e2, flicker}], and for each
after the first against_first {sequence, lower_at, velocities, mean_change,
lowest_change, highest_change}. progress: a
callable f(done, total, note) called as each sequence and velocity finishes,
or None.)doc"));

  // The motions' texts are the library's (kComparisonMotions).
  static const std::string compare_doc =
      R"doc(aapat sequence compare: the rendered comparison study. Each sequence (a
Sequence or a spec; the first is the baseline) is rendered through the engine
preset's full pipeline (settings: overrides by key) at ratio on the same
scenes (a list of scene specs or files, or random_scenes generated
random-shapes:count=shapes,seed=seed+i) under the same motion: )doc" +
      comparison_motion_help() +
      R"doc(. A dict with the keys of `aapat sequence compare --json`:
scenes [{scene, motion, rows [{sequence, rmse, flicker, flip, after a cut
worst_phase {rmse, flicker, flip} and worst_phase_at, resonant
worst_velocity, worst_velocity_at and per_velocity}]}], velocities (resonant,
render px/frame) and against_first (after a cut or resonant also
against_first_worst, on each scene's worst) [{sequence, against,
rmse|flicker|flip: {lower, ties, scenes, mean_difference, low, high,
mean_ratio, sign_p}}] (a paired bootstrap interval over the scenes and an
exact sign test), and warnings [text] when the preset's engine would not run a
sequence as given (FSR 2: a null jitter). progress: a callable f(done, total, note) called after each
render, or None.)doc";
  m.def(
      "sequence_compare",
      [](const std::vector<py::object>& sequences, const std::string& taa, double ratio,
         const py::dict& settings, const std::optional<std::vector<std::string>>& scenes,
         int random_scenes, int shapes, const std::string& motion, uint64_t seed, double max_speed,
         std::pair<int, int> size, int frames, int warmup, int reference_samples,
         const std::string& reference_filter, int resamples, const py::object& progress) {
        EngineComparison c =
            comparison_of(taa, ratio, settings, scenes, random_scenes, shapes, motion, seed,
                          max_speed, size, frames, warmup, reference_samples, reference_filter);
        c.resamples = resamples;
        std::vector<Sequence> seqs;
        for (const py::object& q : sequences) seqs.push_back(sequence_arg(q, ratio));
        validate(c, seqs.size());
        const auto report = progress_of(progress);
        const auto r = interruptible([&] { return compare_under_engine(seqs, c, {}, report); });
        return to_python(engine_comparison_json(c, r));
      },
      py::arg("sequences"), py::kw_only(), py::arg("taa"), py::arg("ratio") = 1.0,
      py::arg("settings") = py::dict(), py::arg("scenes") = py::none(),
      py::arg("random_scenes") = 0, py::arg("shapes") = kDefaultRandomSceneShapes,
      py::arg("motion") = EngineComparison{}.motion, py::arg("seed") = 1,
      py::arg("max_speed") = EngineComparison{}.max_speed,
      py::arg("size") = std::pair<int, int>{EngineComparison{}.width, EngineComparison{}.height},
      py::arg("frames") = EngineComparison{}.frames, py::arg("warmup") = EngineComparison{}.warmup,
      py::arg("reference_samples") = EngineComparison{}.reference.samples,
      py::arg("reference_filter") = EngineComparison{}.reference.filter,
      py::arg("resamples") = EngineComparison{}.resamples, py::arg("progress") = py::none(),
      compare_doc.c_str());

  m.def(
      "sequence_search",
      [](const py::object& start, const std::string& taa, const py::object& against, double ratio,
         const py::dict& settings, const std::optional<std::vector<std::string>>& scenes,
         int random_scenes, int shapes, const std::string& motion, uint64_t seed, double max_speed,
         std::pair<int, int> size, int frames, int warmup, int reference_samples,
         const std::string& reference_filter, double step, double min_step, double loss,
         double jitter_bound, int max_tries, bool worst, bool unbiased,
         const std::vector<std::string>& also_motions, const py::object& progress) {
        RenderedSearch s;
        s.comparison =
            comparison_of(taa, ratio, settings, scenes, random_scenes, shapes, motion, seed,
                          max_speed, size, frames, warmup, reference_samples, reference_filter);
        s.start = sequence_arg(start, ratio);
        s.baseline = against.is_none() ? resolve_sequence(s.comparison.taa.jitter)
                                       : sequence_arg(against, ratio);
        s.step = step;
        s.min_step = min_step;
        s.loss = loss;
        s.jitter_bound = jitter_bound;
        s.max_tries = max_tries;
        s.worst = worst;
        s.unbiased = unbiased;
        s.also_motions = also_motions;
        validate(s);
        const auto report = progress_of(progress);
        const auto r = interruptible([&] { return search_rendered(s, {}, report); });
        py::dict d = to_python(rendered_search_json(s, r));
        d["result"] = r.best;
        return d;
      },
      py::arg("start"), py::kw_only(), py::arg("taa"), py::arg("against") = py::none(),
      py::arg("ratio") = 1.0, py::arg("settings") = py::dict(), py::arg("scenes") = py::none(),
      py::arg("random_scenes") = 0, py::arg("shapes") = kDefaultRandomSceneShapes,
      py::arg("motion") = EngineComparison{}.motion, py::arg("seed") = 1,
      py::arg("max_speed") = EngineComparison{}.max_speed,
      py::arg("size") = std::pair<int, int>{EngineComparison{}.width, EngineComparison{}.height},
      py::arg("frames") = EngineComparison{}.frames, py::arg("warmup") = EngineComparison{}.warmup,
      py::arg("reference_samples") = EngineComparison{}.reference.samples,
      py::arg("reference_filter") = EngineComparison{}.reference.filter,
      py::arg("step") = RenderedSearch{}.step, py::arg("min_step") = RenderedSearch{}.min_step,
      py::arg("loss") = RenderedSearch{}.loss,
      py::arg("jitter_bound") = RenderedSearch{}.jitter_bound, py::arg("max_tries") = 0,
      py::arg("worst") = RenderedSearch{}.worst, py::arg("unbiased") = RenderedSearch{}.unbiased,
      py::arg("also_motions") = std::vector<std::string>{}, py::arg("progress") = py::none(),
      R"doc(aapat sequence search: a jitter searched on rendered error. A compass search
from `start` (a Sequence or spec) whose objective renders the sequence through
the engine preset's full pipeline on the scenes (as sequence_compare takes
them) against `against` (default: the preset's own jitter): the mean over the
scenes of log(rmse ratio) + log(flip ratio) + loss (their positive parts) +
(1 + loss) (the positive part of log(flicker ratio)), so a scene lost weighs
1 + loss and flicker counts only where it rises; worst=True takes each
scene's worst phase (motion "cut") or resonant velocity ("resonant");
unbiased=True keeps the frames' mean jitter at (0, 0), as XeSS asks (each
trial rendered centred); also_motions: further motions searched at once (the objective is the mean over
the motions). A dict with the keys of `aapat sequence search
--json` (start_value, value, tries, kept, ...), its "result" the
aapat.Sequence found. progress: a callable f(done, total, note) as each step
size finishes, or None.)doc");
}

}  // namespace aapat::python
