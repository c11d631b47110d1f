// Filters and acuity tables by spec, E2 (one pattern, many, or an (m, n, 2)
// array of one-pixel patterns in one vectorized call) and the per-angle profile.
#include <fmt/format.h>

#include <tbb/task_arena.h>

#include <cmath>
#include <deque>
#include <optional>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/point_checks.h"
#include "aapat/study/batch_e2.h"
#include "aapat/study/eval_study.h"
#include "aapat/work/work_items.h"
#include "bindings.h"

namespace aapat::python {

const char* with_metric_args(const char* text) {
  static std::deque<std::string> kept;
  return kept.emplace_back(std::string(text) + kMetricArgs).c_str();
}

namespace {

std::optional<std::string> spec_of(const py::object& value, const char* what) {
  if (value.is_none()) return std::nullopt;
  if (py::isinstance<Filter>(value)) return value.cast<const Filter&>().name();
  if (py::isinstance<AcuityTable>(value)) return value.cast<const AcuityTable&>().name;
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  throw Error(fmt::format("{}: expected a spec (str), an aapat.{} or None, not {}", what,
                          std::string(what) == "filter" ? "Filter" : "AcuityTable",
                          py::str(py::type::of(value).attr("__name__")).cast<std::string>()));
}

}  // namespace

Objective make_objective(const py::object& objective, const py::object& filter,
                         const py::object& acuity, const py::object& norm) {
  if (!py::isinstance<py::str>(objective))
    throw Error("objective: expected a name or spec (str), e.g. 'recommended' or 'laine-aila'");
  std::optional<double> p;
  if (py::isinstance<py::str>(norm)) {
    p = parse_norm(norm.cast<std::string>(), "norm");
  } else if (!norm.is_none()) {
    if (!py::isinstance<py::float_>(norm) && !py::isinstance<py::int_>(norm))
      throw Error("norm: expected a number, 'inf' or None");
    p = norm.cast<double>();
  }
  return override_objective(parse_objective(objective.cast<std::string>(), "objective"),
                            spec_of(filter, "filter"), spec_of(acuity, "acuity"), p);
}

py::object to_python(const JsonObject& json) {
  return py::module_::import("json").attr("loads")(json_text(json));
}

void check_samples(const Array& xy, const char* what) {
  check_in_pixel({xy.data(), static_cast<size_t>(xy.size())}, what);
}

namespace {

// E2 of every one-pixel pattern of an (m, n, 2) array, weights (m, n), (n,) or None.
Array batch_eval(const Metric& metric, const Array& xy, const py::object& weights, int threads) {
  if (xy.ndim() != 3 || xy.shape(2) != 2 || xy.shape(1) < 1)
    throw Error("eval: expected an (m, n, 2) array of m patterns of n >= 1 samples");
  check_samples(xy, "eval");
  const size_t m = static_cast<size_t>(xy.shape(0)), n = static_cast<size_t>(xy.shape(1));
  std::vector<double> w;
  if (!weights.is_none()) {
    const Array a = to_array(weights, "weights");
    if (a.ndim() == 1 && static_cast<size_t>(a.shape(0)) == n) {
      for (size_t p = 0; p < m; ++p) w.insert(w.end(), a.data(), a.data() + n);
    } else if (a.ndim() == 2 && static_cast<size_t>(a.shape(0)) == m &&
               static_cast<size_t>(a.shape(1)) == n) {
      w.assign(a.data(), a.data() + m * n);
    } else {
      throw Error(fmt::format("eval: weights must be ({}, {}) or ({},)", m, n, n));
    }
    for (double v : w)
      if (!std::isfinite(v)) throw Error("eval: weights must be finite numbers");
  }
  Array out(static_cast<py::ssize_t>(m));
  std::span<double> e2(out.mutable_data(), m);
  const std::span<const double> coords(xy.data(), m * n * 2);
  check_threads(threads, "eval: threads");
  interruptible([&] {
    if (threads == 0) {
      batch_e2(metric, coords, w, m, n, e2);
    } else {
      tbb::task_arena arena(threads);
      arena.execute([&] { batch_e2(metric, coords, w, m, n, e2); });
    }
  });
  return out;
}

// The profiles of every one-pixel pattern of an (m, n, 2) array, equal weights.
py::dict batch_profiles(const Metric& metric, const Array& xy) {
  if (xy.ndim() != 3 || xy.shape(2) != 2 || xy.shape(1) < 1)
    throw Error("profile: expected an (m, n, 2) array of m patterns of n >= 1 samples");
  check_samples(xy, "profile");
  const size_t m = static_cast<size_t>(xy.shape(0)), n = static_cast<size_t>(xy.shape(1));
  const size_t angles = static_cast<size_t>(metric.angle_count());
  Array values({static_cast<py::ssize_t>(m), static_cast<py::ssize_t>(angles)});
  Array e2(static_cast<py::ssize_t>(m));
  const std::span<const double> coords(xy.data(), m * n * 2);
  interruptible([&] {
    batch_profile(metric, coords, {}, m, n, {values.mutable_data(), m * angles});
    batch_e2(metric, coords, {}, m, n, {e2.mutable_data(), m});
  });
  return py::dict(py::arg("angles_deg") = from_vector(metric.acuity().angles_deg),
                  py::arg("values") = values, py::arg("e2") = e2);
}

}  // namespace

void bind_metric(py::module_& m) {
  py::class_<Filter>(m, "Filter", "A reference filter h(x), separable in 2D: h(x) h(y).")
      .def(py::init([](const std::string& spec) { return make_filter(spec); }), py::arg("spec"))
      .def_property_readonly("name", &Filter::name,
                             "the canonical spec, e.g. 'mitchell:b=1/3,c=1/3'")
      .def_property_readonly("radius", &Filter::radius, "the support's half width in pixels")
      .def(
          "__call__",
          [](const Filter& f, const Array& x) {
            Array out(x.request().shape);
            for (py::ssize_t i = 0; i < x.size(); ++i) out.mutable_data()[i] = f.value(x.data()[i]);
            return out;
          },
          py::arg("x"), "h at every x of an array (1D, unnormalized)")
      .def("__repr__", [](const Filter& f) { return "<aapat.Filter " + f.name() + ">"; });
  m.def(
      "filter", [](const std::string& spec) { return make_filter(spec); }, py::arg("spec"),
      "a filter by spec, e.g. aapat.filter('gaussian:sigma=0.5,radius=1.5')");

  py::class_<AcuityTable>(m, "AcuityTable", "Edge angles and their weights W(theta).")
      .def(py::init([](const std::string& spec) { return make_acuity(spec); }), py::arg("spec"))
      .def_readonly("name", &AcuityTable::name)
      .def_property_readonly("angles_deg",
                             [](const AcuityTable& a) { return from_vector(a.angles_deg); })
      .def_property_readonly("weights",
                             [](const AcuityTable& a) { return from_vector(a.weights); });
  m.def(
      "acuity", [](const std::string& spec) { return make_acuity(spec); }, py::arg("spec"),
      "an acuity table: 'laine-aila', 'uniform:step=S', 'linear:step=S' or a CSV file");

  m.def(
      "eval",
      [](const py::object& patterns, const py::object& weights, int threads,
         const py::object& objective, const py::object& filter, const py::object& acuity,
         const py::object& norm) -> py::object {
        check_threads(threads, "eval: threads");  // on every path, used or not
        const Metric metric = make_metric(objective, filter, acuity, norm);
        if (py::isinstance<py::array>(patterns)) {
          const Array xy = to_array(patterns, "patterns");
          if (xy.ndim() == 2) {  // one pattern
            Array batch = Array(xy).reshape({py::ssize_t{1}, xy.shape(0), xy.shape(1)});
            return py::float_(batch_eval(metric, batch, weights, threads).at(0));
          }
          return batch_eval(metric, xy, weights, threads);
        }
        if (py::isinstance<py::list>(patterns) || py::isinstance<py::tuple>(patterns)) {
          std::vector<Pattern> list;
          for (const py::handle& h : patterns) list.push_back(to_pattern(h));
          std::vector<double> e2(list.size());
          interruptible([&] {  // Metric::evaluate stops between patterns
            for (size_t i = 0; i < list.size(); ++i) e2[i] = metric.evaluate(list[i]).e2;
          });
          return from_vector(e2);
        }
        return py::float_(metric.evaluate(to_pattern(patterns)).e2);
      },
      py::arg("patterns"), py::arg("weights") = py::none(), py::arg("threads") = 0,
      AAPAT_OBJECTIVE_ARGS,
      with_metric_args(R"doc(E2 of patterns under the Laine-Aila weighted error metric.

    patterns: a catalog name or pattern file, an aapat.Pattern, a list of those
        (returns an array), an (n, 2) array of one pixel's samples (returns a
        float), or an (m, n, 2) array of m such patterns, evaluated in one
        vectorized call in parallel (returns an (m,) array). Coordinates in
        pixels from the pixel centre.
    weights: for arrays, (n,) or (m, n) resolve weights (normalized per
        pattern); None: equal weights.
    threads: for arrays, the threads to use (0: all cores); the result is the
        same for any count.)doc"));

  m.def(
      "eval_report",
      [](const py::object& patterns, bool optimized_weights, const py::object& objective,
         const py::object& filter, const py::object& acuity, const py::object& norm) {
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Metric metric = o.metric();
        std::vector<Pattern> list;
        if (py::isinstance<py::list>(patterns) || py::isinstance<py::tuple>(patterns)) {
          for (const py::handle& h : patterns) list.push_back(to_pattern(h));
        } else {
          list.push_back(to_pattern(patterns));
        }
        const auto evaluations = interruptible(
            [&] { return evaluate_patterns(metric, list, optimized_weights, false); });
        return to_python(eval_json(o, metric.angle_count(), list, evaluations));
      },
      py::arg("patterns"), py::arg("optimized_weights") = false, AAPAT_OBJECTIVE_ARGS,
      with_metric_args(R"doc(The `aapat eval --json` document of patterns (a name, file, Pattern,
or a list of them): objective, filter, acuity, norm, angles and a row per
pattern (pattern, family, n, e2, worst_angle_deg, worst_kernel, kernel_e2,
and e2_optimized_weights with optimized_weights=True).)doc"));

  m.def(
      "profile",
      [](const py::object& pattern, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) -> py::dict {
        const Metric metric = make_metric(objective, filter, acuity, norm);
        if (py::isinstance<py::array>(pattern))
          return batch_profiles(metric, to_array(pattern, "pattern"));
        const Pattern p = to_pattern(pattern);
        const PatternError e = metric.evaluate(p);
        Array values({static_cast<py::ssize_t>(p.set_count()),
                      static_cast<py::ssize_t>(metric.angle_count())});
        for (int k = 0; k < p.set_count(); ++k) {
          const std::vector<double> v = metric.profile(make_kernel(p, k));
          std::copy(v.begin(), v.end(), values.mutable_data() + k * metric.angle_count());
        }
        return py::dict(py::arg("angles_deg") = from_vector(metric.acuity().angles_deg),
                        py::arg("values") = values, py::arg("e2") = e.e2,
                        py::arg("kernel_e2") = from_vector(e.kernel_e2),
                        py::arg("worst_kernel") = e.worst_kernel,
                        py::arg("worst_angle_deg") = e.worst_angle_deg);
      },
      py::arg("pattern"), AAPAT_OBJECTIVE_ARGS,
      with_metric_args(R"doc(The per-angle profile W(theta) E1(theta) of every kernel of a pattern.

Returns a dict: angles_deg (the acuity table's angles), values (kernels x
angles), e2, kernel_e2, worst_kernel, worst_angle_deg. For an (m, n, 2) array
of m one-pixel patterns (equal weights), in one vectorized call: angles_deg,
values (m x angles) and e2 (m,).)doc"));
}

}  // namespace aapat::python
