// The pieces of the Python module `aapat` (one file per area) and the numpy
// conversions they share. Arrays are copied in and out: what Python holds
// never aliases the library's memory.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "aapat/core/pattern.h"
#include "aapat/io/json_report.h"
#include "interruptible.h"

namespace aapat::python {

namespace py = pybind11;
using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

void bind_patterns(py::module_& m);
void bind_metric(py::module_& m);
void bind_optimize(py::module_& m);
void bind_points(py::module_& m);
void bind_render(py::module_& m);
void bind_studies(py::module_& m);
void bind_temporal(py::module_& m);
// Wraps every function, method and constructor of m so that arguments of the
// wrong type raise aapat.Error (pybind11 raises TypeError).
void strict_arguments(py::module_& m);

// Any array-like value as an array of doubles, else aapat.Error naming
// `what` (numpy's own ValueError or TypeError does not escape).
Array to_array(const py::handle& value, const char* what);

// (n, 2) array <-> points.
std::vector<Vec2> to_points(const Array& a, const char* what);
Array from_points(const std::vector<Vec2>& points);
Array from_vector(const std::vector<double>& v);

// A pattern given as a catalog name, a file path or a Pattern.
Pattern to_pattern(const py::handle& h);

// The objective of the keyword arguments objective= (a name or spec, the
// library's default when not given) and its overrides filter=, acuity=,
// norm= (None: the objective's; specs, or Filter / AcuityTable objects).
Objective make_objective(const py::object& objective, const py::object& filter,
                         const py::object& acuity, const py::object& norm);
inline Metric make_metric(const py::object& objective, const py::object& filter,
                          const py::object& acuity, const py::object& norm) {
  return make_objective(objective, filter, acuity, norm).metric();
}
// The keyword arguments above with their defaults, in order.
#define AAPAT_OBJECTIVE_ARGS                                                             \
  py::arg("objective") = std::string(kDefaultObjective), py::arg("filter") = py::none(), \
  py::arg("acuity") = py::none(), py::arg("norm") = py::none()

// A JSON object the library made, as Python values (dicts, lists, floats):
// the same keys as the command line's --json.
py::object to_python(const JsonObject& json);

// An engine preset's overrides from a dict {key: value} (values as text,
// as `--taa-set KEY=VALUE` gives them).
inline std::vector<std::pair<std::string, std::string>> taa_overrides_of(const py::dict& settings) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : settings)
    out.emplace_back(key.cast<std::string>(), py::str(value).cast<std::string>());
  return out;
}

// A library document's rows (a list of dicts with the CLI's keys), or its
// values without "command" and "schema".
inline py::object rows_of(const JsonObject& doc) {
  return to_python(doc.at("rows"));
}
inline py::object values_of(JsonObject doc) {
  doc.erase("command");
  doc.erase("schema");
  return to_python(doc);
}

// An (m, n, 2) or (n, 2) array of samples in pixels from the centre: finite,
// inside the pixel, else aapat.Error naming the sample.
void check_samples(const Array& xy, const char* what);

// A progress callable (done, total, note), called with the GIL held; None:
// silent (Ctrl-C is heard by interruptible() either way).
std::function<void(int, int, const std::string&)> progress_of(const py::object& callback);

// The docstring of the metric keywords, shared by the functions that take them.
inline constexpr const char* kMetricArgs = R"doc(
    objective: what E2 means: "recommended" (default: the study's, the
        catalog's), "laine-aila" (the papers'), or "filter=F acuity=A norm=P"
        (aapat.registry()["objectives"]).
    filter: instead of the objective's reference filter, a spec such as
        "mitchell:b=1/3,c=1/3", "gaussian:sigma=0.5,radius=1.5" or "lanczos:lobes=3"
        (aapat.registry()["filters"]), or an aapat.Filter.
    acuity: instead of the objective's angle acuity table: "laine-aila",
        "uniform:step=S", "linear:step=S", a CSV file, or an aapat.AcuityTable.
    norm: instead of the objective's p of the L_p mean over angles; inf is the
        maximum of Laine-Aila Eq. 5.)doc";

// `text` followed by kMetricArgs, kept for the module's lifetime (pybind11
// keeps the pointer).
const char* with_metric_args(const char* text);

}  // namespace aapat::python
