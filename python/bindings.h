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
#include "aapat/core/pattern.h"

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

// (n, 2) array <-> points.
std::vector<Vec2> to_points(const Array& a, const char* what);
Array from_points(const std::vector<Vec2>& points);
Array from_vector(const std::vector<double>& v);

// A pattern given as a catalog name, a file path or a Pattern.
Pattern to_pattern(const py::handle& h);

// The metric of the keyword arguments filter=, acuity=, norm= (specs, or
// Filter / AcuityTable objects).
Metric make_metric(const py::object& filter, const py::object& acuity, double norm);

// A progress callable (done, total, note), called with the GIL held; None: silent.
std::function<void(int, int, const std::string&)> progress_of(const py::object& callback);

// The docstring of the metric keywords, shared by the functions that take them.
inline constexpr const char* kMetricArgs = R"doc(
    filter: the reference filter, a spec such as "mitchell:b=1/3,c=1/3",
        "gaussian:sigma=0.5,radius=1.5" or "lanczos:lobes=3" (aapat.registry()["filters"]),
        or an aapat.Filter. Default "mitchell".
    acuity: the angle acuity table: "laine-aila" (default), "uniform:step=S",
        "linear:step=S", a CSV file, or an aapat.AcuityTable.
    norm: p of the L_p mean over angles; inf (default) is the maximum of Laine-Aila Eq. 5.)doc";

// `text` followed by kMetricArgs, kept for the module's lifetime (pybind11
// keeps the pointer).
const char* with_metric_args(const char* text);

}  // namespace aapat::python
