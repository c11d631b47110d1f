// `import aapat`: the library from Python with numpy arrays. Library errors
// arrive as aapat.Error (a ValueError and a TypeError) with the library's
// message, a wrong argument's type too.
#include <algorithm>

#include "aapat/core/text.h"
#include "aapat/version.h"
#include "bindings.h"

namespace aapat::python {

PYBIND11_MODULE(aapat, m) {
  m.doc() = R"doc(aapat: antialiasing sample patterns.

The Laine-Aila E2 metric and its optimizer, the P(s, r, n) pattern families with
samples shared on pixel borders, the enumeration of the P(4,1+,n) schemes,
point sets with their spectra and discrepancies, and a test renderer, on numpy
arrays. Specs name filters, acuity tables, generators and scenes
("name:key=value,..."); aapat.registry() lists them all.)doc";
  m.attr("__version__") = AAPAT_VERSION;
  // Every array the module takes or gives is numpy's: without numpy, the
  // import itself fails and says what to install (not the first call that
  // returns an array, with pybind11's message).
  try {
    py::module_::import("numpy");
  } catch (py::error_already_set&) {
    throw py::import_error(
        "aapat needs numpy: install it (Debian: apt-get install python3-numpy; or pip install "
        "numpy) and import aapat again");
  }
  // aapat.Error is a ValueError (a bad value) and a TypeError (a value of the
  // wrong type, see strict_arguments.cpp).
  static py::exception<Error>& error = py::register_exception<Error>(
      m, "Error", py::make_tuple(py::handle(PyExc_ValueError), py::handle(PyExc_TypeError)));
  // A setting the library names as the command line's flag (max-per-edge)
  // is named here as the keyword that gives it (max_per_edge).
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ParameterError& e) {
      std::string keyword = e.parameter();
      std::replace(keyword.begin(), keyword.end(), '-', '_');
      PyErr_SetString(error.ptr(), shortened_message(keyword + e.detail()).c_str());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), shortened_message(e.what()).c_str());
    } catch (const py::cast_error& e) {
      // A value converted inside a function (a list where a sequence or a
      // pattern was expected): aapat.Error like every bad input, not
      // pybind11's RuntimeError.
      PyErr_SetString(
          error.ptr(),
          (std::string("an argument is not of a type this function takes (") + e.what() + ")")
              .c_str());
    }
  });
  m.attr("Error").attr("__doc__") =
      "A library error: bad input named with the spec, parameter or file at fault.";
  bind_patterns(m);
  bind_metric(m);
  bind_optimize(m);
  bind_points(m);
  bind_render(m);
  bind_studies(m);
  bind_temporal(m);
  strict_arguments(m);  // last: it wraps every function defined above
}

}  // namespace aapat::python
