// `import aapat`: the library from Python with numpy arrays. Library errors
// arrive as aapat.Error (a ValueError) with the library's message.
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
  py::register_exception<Error>(m, "Error", PyExc_ValueError);
  m.attr("Error").attr("__doc__") =
      "A library error: bad input named with the spec, parameter or file at fault.";
  bind_patterns(m);
  bind_metric(m);
  bind_optimize(m);
  bind_points(m);
  bind_render(m);
  bind_studies(m);
  bind_temporal(m);
}

}  // namespace aapat::python
