// Patterns from and to numpy arrays and files; the registries of specs.
#include <fmt/format.h>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/aapat_catalog.h"
#include "aapat/io/pattern_json.h"
#include "aapat/registry/limits_table.h"
#include "aapat/registry/spec_registries.h"
#include "aapat/render/scene.h"
#include "aapat/render/texture_filter.h"
#include "bindings.h"

namespace aapat::python {

Array to_array(const py::handle& value, const char* what) {
  try {
    return value.cast<Array>();
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
    throw Error(fmt::format("{}: not an array of numbers ({})", what, e.what()));
  }
}

std::vector<Vec2> to_points(const Array& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 2) {
    std::string shape;
    for (py::ssize_t d = 0; d < a.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw Error(fmt::format("{}: expected an (n, 2) array of x, y, not shape ({})", what, shape));
  }
  std::vector<Vec2> points(static_cast<size_t>(a.shape(0)));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) points[i] = {r(i, 0), r(i, 1)};
  return points;
}

Array from_points(const std::vector<Vec2>& points) {
  Array a({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto w = a.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) w(i, 0) = points[i].x, w(i, 1) = points[i].y;
  return a;
}

Array from_vector(const std::vector<double>& v) {
  Array a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

Pattern to_pattern(const py::handle& h) {
  if (py::isinstance<Pattern>(h)) return h.cast<Pattern>();
  if (py::isinstance<py::str>(h)) return resolve_pattern(h.cast<std::string>());
  throw Error("pattern: give a catalog name, a pattern file or an aapat.Pattern");
}

namespace {

// One pixel's pattern from (n, 2) positions and n weights (equal when None).
Pattern pattern_from_arrays(const Array& positions, const py::object& weights,
                            const std::string& name) {
  const std::vector<Vec2> points = to_points(positions, "positions");
  std::vector<double> w(points.size(), points.empty() ? 0.0 : 1.0 / points.size());
  if (!weights.is_none()) {
    const Array a = to_array(weights, "weights");
    if (a.ndim() != 1 || static_cast<size_t>(a.shape(0)) != points.size())
      throw Error(fmt::format("weights: expected {} weights, one per position", points.size()));
    w.assign(a.data(), a.data() + a.shape(0));
  }
  Pattern p = single_pixel_pattern(name, points, w);
  validate(p);
  return p;
}

py::dict info_dict(const SpecInfo& info) {
  py::list params;
  for (const ParamInfo& p : info.params)
    params.append(py::dict(py::arg("key") = p.key,
                           py::arg("default") = p.default_text.empty()
                                                    ? py::object(py::none())
                                                    : py::object(py::str(p.default_text)),
                           py::arg("meaning") = p.meaning));
  return py::dict(py::arg("name") = info.name, py::arg("usage") = info.usage(),
                  py::arg("summary") = info.summary, py::arg("source") = info.source,
                  py::arg("parameters") = params);
}

template <class R>
py::list infos(const R& registry) {
  py::list l;
  for (const auto& e : registry.entries()) l.append(info_dict(e.info));
  return l;
}

}  // namespace

void bind_patterns(py::module_& m) {
  py::class_<Pattern>(
      m, "Pattern",
      R"doc(A sample pattern: a tile of pixel sets, a footprint, and per-kernel weights.

Construct a one-pixel pattern P(1,1,n) from numpy arrays:
    aapat.Pattern(positions, weights=None, name="pattern")
positions: (n, 2) array of x, y in pixels from the pixel centre, in [-1/2, 1/2];
weights: n resolve weights (equal when None). Any family comes from
aapat.pattern(name or file), aapat.optimize(...) or Pattern.from_json.)doc")
      .def(py::init(&pattern_from_arrays), py::arg("positions"), py::arg("weights") = py::none(),
           py::arg("name") = "pattern")
      .def_readonly("name", &Pattern::name)
      .def_readonly("description", &Pattern::description)
      .def_property_readonly(
          "tile", [](const Pattern& p) { return py::make_tuple(p.tile_w, p.tile_h); },
          "(width, height) of the tile in pixels")
      .def_property_readonly(
          "footprint",
          [](const Pattern& p) {
            return fmt::format("{}{}", p.footprint.pixels(), p.footprint.plus ? "+" : "");
          },
          "r of P(s, r, n): the kernel's pixels, '+' when it reads the shared border samples")
      .def_property_readonly(
          "family", [](const Pattern& p) { return family(p); }, "the family, e.g. 'P(4,1+,2)'")
      .def_property_readonly("samples_per_pixel", &samples_per_pixel,
                             "n: distinct samples per pixel (shared border samples count once)")
      .def_property_readonly(
          "sets",
          [](const Pattern& p) {
            py::list l;
            for (const auto& s : p.sets) l.append(from_points(s));
            return l;
          },
          "the tile's pixel sets: one (n_k, 2) array per pixel, row-major from the bottom left")
      .def_property_readonly(
          "weights",
          [](const Pattern& p) {
            py::list l;
            for (const auto& w : p.weights) l.append(from_vector(w));
            return l;
          },
          "per kernel, the weights of the samples it reads (aapat.kernel_samples order)")
      .def_property_readonly(
          "provenance",
          [](const Pattern& p) {
            py::dict d;
            for (const auto& [k, v] : p.provenance) d[py::str(k)] = v;
            return d;
          },
          "where the pattern came from: optimizer, seed, E2, ...")
      .def("to_json", &pattern_to_json, "the pattern file's text (docs/patterns.md)")
      .def_static(
          "from_json", [](const std::string& text) { return pattern_from_json(text, "json"); },
          py::arg("text"), "a pattern from a pattern file's text")
      .def(
          "save", [](const Pattern& p, const std::string& path) { save_pattern_file(p, path); },
          py::arg("path"), "write a .json pattern file, or Laine's x y weight text (.xyw)")
      .def("__repr__", [](const Pattern& p) {
        return fmt::format("<aapat.Pattern {} {} n={}>", p.name, family(p),
                           format_cost(samples_per_pixel(p)));
      });

  m.def(
      "pattern", [](const std::string& name) { return resolve_pattern(name); }, py::arg("name"),
      R"doc(A catalog pattern ("rgss", "flipquad", "hasselgren-f", "grid-4x4", ...) or a
pattern file (.json, or Laine's x y weight text .xyw).)doc");
  m.def(
      "load_pattern", [](const std::string& path) { return load_pattern_file(path); },
      py::arg("path"), "read a pattern file (.json or .xyw)");
  m.def(
      "save_pattern", [](const Pattern& p, const std::string& path) { save_pattern_file(p, path); },
      py::arg("pattern"), py::arg("path"),
      "write a pattern file (.json or .xyw), whole or not at all");
  m.def(
      "registry",
      [] {
        py::dict d;
        for (const RegistrySection& section : registry_sections()) {
          py::list entries;
          for (const SpecInfo& info : section.infos) entries.append(info_dict(info));
          d[py::str(section.key)] = entries;
        }
        return d;
      },
      R"doc(Every registry of specs, as `aapat list` prints them: a dict from kind
("objectives", "patterns", "aapat_patterns", "filters", "generators", "acuity_tables", "scenes",
"textures", "texture_filters", "api_profiles", "motions", "sequences", "aapat_sequences",
"taa_presets")
to a list of {name, usage, summary, source, parameters}.)doc");
  m.def(
      "limits", [] { return to_python(limits_json().at("limits")); },
      R"doc(Every limit aapat checks, as `aapat limits --json` lists them (and
docs/limits.md shows them): a list of {what, limit, defined}. The same
limits hold here as on the command line; a value past one raises aapat.Error.)doc");
}

}  // namespace aapat::python
