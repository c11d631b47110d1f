// Sequences over time: generate or load, evaluate under an accumulation
// model, optimize (docs/temporal.md).
#include "aapat/core/filter_catalog.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_json.h"
#include "aapat/temporal/sequence_optimizer.h"
#include "aapat/temporal/temporal_metrics.h"
#include "bindings.h"

namespace aapat::python {
namespace {

Accumulation make_model(const std::string& model, double alpha, int window,
                        const std::string& resolve) {
  Accumulation a;
  if (model != "ema" && model != "box") throw Error("model '" + model + "': expected ema or box");
  a.kind = model == "box" ? AccumulationKind::box : AccumulationKind::ema;
  a.alpha = alpha;
  a.window = window;
  if (!resolve.empty()) a.resolve = make_filter(resolve);
  validate(a);
  return a;
}

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
"sobol:frames=16,seed=1", "msaa-alternating:samples=2,frames=2", "split:frames=K"
with pattern=...), a name of the optimized ones ("aapat-taa-8") or a file.)doc");

  m.def(
      "sequence_eval",
      [](const py::object& seq, const std::string& model, double alpha, int window,
         const std::string& resolve, const py::object& filter, const py::object& acuity,
         double norm) {
        const Sequence s = py::isinstance<Sequence>(seq)
                               ? seq.cast<Sequence>()
                               : resolve_sequence(seq.cast<std::string>());
        const Metric metric = make_metric(filter, acuity, norm);
        const Accumulation a = make_model(model, alpha, window, resolve);
        TemporalReport r;
        {
          py::gil_scoped_release release;
          r = evaluate_temporal(s, a, metric);
        }
        return py::dict(py::arg("worst_e2") = r.worst_e2, py::arg("mean_e2") = r.mean_e2,
                        py::arg("steady_e2") = from_vector(r.steady_e2),
                        py::arg("cut_curve") = from_vector(r.cut_curve),
                        py::arg("settle_frame") = r.settle_frame,
                        py::arg("flicker") = r.mean_flicker,
                        py::arg("worst_flicker") = r.worst_flicker,
                        py::arg("flicker_per_transition") = from_vector(r.flicker),
                        py::arg("mean_offset") = py::make_tuple(r.mean_offset.x, r.mean_offset.y),
                        py::arg("worst_centroid") = r.worst_centroid);
      },
      py::arg("sequence"), py::kw_only(), py::arg("model") = "ema", py::arg("alpha") = 0.1,
      py::arg("window") = 0, py::arg("resolve") = "", py::arg("filter") = "mitchell",
      py::arg("acuity") = "uniform:step=1", py::arg("norm") = 2.0,
      with_metric_args(
          (std::string(R"doc(The temporal metrics of a sequence (a Sequence or a spec) under an
accumulation model: a dict of worst_e2, mean_e2, steady_e2, cut_curve, settle_frame,
flicker (the mean over transitions), worst_flicker, flicker_per_transition,
mean_offset, worst_centroid. The default objective is the study's (uniform:step=1, L2).)doc") +
           kModelArgs)
              .c_str()));

  m.def(
      "optimize_sequence",
      [](int frames, int samples_per_frame, double flicker_weight, const std::string& measure,
         int starts, uint64_t seed, const std::string& model, double alpha, int window,
         const py::object& filter, const py::object& acuity, double norm) {
        SequenceSearch s;
        s.frames = frames;
        s.samples_per_frame = samples_per_frame;
        s.flicker_weight = flicker_weight;
        if (measure != "worst" && measure != "mean")
          throw Error("measure '" + measure + "': expected worst or mean");
        s.frame_measure = measure == "mean" ? FrameMeasure::mean : FrameMeasure::worst;
        s.starts = starts;
        s.seed = seed;
        s.model = make_model(model, alpha, window, "");
        const Metric metric = make_metric(filter, acuity, norm);
        SequenceSearchResult r;
        {
          py::gil_scoped_release release;
          r = optimize_sequence(s, metric);
        }
        return py::dict(py::arg("sequence") = r.best, py::arg("objective") = r.objective,
                        py::arg("worst_e2") = r.worst_e2, py::arg("mean_e2") = r.mean_e2,
                        py::arg("flicker") = r.flicker, py::arg("best_start") = r.best_start,
                        py::arg("halton_objective") = r.halton_objective);
      },
      py::kw_only(), py::arg("frames") = 8, py::arg("samples_per_frame") = 1,
      py::arg("flicker_weight") = 3.0, py::arg("measure") = "worst", py::arg("starts") = 16,
      py::arg("seed") = 1, py::arg("model") = "ema", py::arg("alpha") = 0.1, py::arg("window") = 0,
      py::arg("filter") = "mitchell", py::arg("acuity") = "uniform:step=1", py::arg("norm") = 2.0,
      R"doc(aapat optimize --sequence: the positions of every frame's samples minimizing
worst (or mean) steady E2 + flicker_weight x flicker under the model. The same
sequence as the command line for the same seed. A dict with the Sequence.)doc");
}

}  // namespace aapat::python
