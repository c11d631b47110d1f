// Point sets: the generators, the peers' file formats, discrepancies and spectra.
#include <fmt/format.h>

#include "aapat/generate/point_generators.h"
#include "aapat/io/point_formats.h"
#include "aapat/study/study_json.h"
#include "bindings.h"

namespace aapat::python {
namespace {

// An (n, 2) array or a list of them.
PointSets to_sets(const py::object& points) {
  PointSets sets;
  if (py::isinstance<py::list>(points) || py::isinstance<py::tuple>(points)) {
    for (const py::handle& h : points) sets.push_back(to_points(to_array(h, "points"), "points"));
  } else {
    sets.push_back(to_points(to_array(points, "points"), "points"));
  }
  return sets;
}

}  // namespace

void bind_points(py::module_& m) {
  m.def(
      "generate",
      [](const std::string& spec, int n, uint64_t seed, const py::object& progress) {
        const auto report = progress_of(progress);
        const auto points = interruptible([&] { return generate_points(spec, n, seed, report); });
        return from_points(points);
      },
      py::arg("spec"), py::arg("n"), py::arg("seed") = 1, py::kw_only(),
      py::arg("progress") = py::none(),
      R"doc(n points in [0,1)^2 from a generator spec, as an (n, 2) array.

    spec: "jittered", "poisson:radius=R", "best-candidate:q=10", "halton:b1=2,b2=3",
        "n-queens", ... (aapat.registry()["generators"]).
    seed: random seed (the deterministic generators ignore it).
    progress: a callable (done, total, note) that the slow generators (dart
        throwing, best candidate) call as they go, in hundredths.)doc");

  m.def(
      "read_points",
      [](const std::string& path, const std::string& format) {
        py::list l;
        for (const auto& set : load_point_sets(path, format)) l.append(from_points(set));
        return l;
      },
      py::arg("path"), py::arg("format") = "",
      R"doc(Every point set of a file, as a list of (n, 2) arrays.

    format: "csv" (aapat), "safari" (Samplin' Safari CSV), "utk" (UTK text .dat,
        sets separated by '#'), "utk-bin" (UTK .bin), "psa" (PSA text), "pspec"
        (pbrt-v4 pspec float32 pairs), "json" (a pattern file); default: by extension.)doc");
  m.def(
      "write_points",
      [](const std::string& path, const py::object& points, const std::string& format) {
        save_point_sets(to_sets(points), path, format);
      },
      py::arg("path"), py::arg("points"), py::arg("format") = "",
      "write an (n, 2) array, or a list of them (utk, utk-bin), in a format of read_points");

  m.def(
      "discrepancy",
      [](const Array& points, const std::string& measures) {
        const std::vector<Vec2> p = to_points(points, "points");
        const DiscrepancyMeasures m = parse_measures(measures);
        const auto d = interruptible([&] { return discrepancy_report(p, m); });
        return values_of(discrepancy_json("", d));
      },
      py::arg("points"), py::arg("measures") = std::string(kDefaultDiscrepancyMeasures),
      R"doc(Discrepancies of an (n, 2) array in [0, 1]^2: the L2 kinds (star, Warnock;
generalized, centred, wrap-around, symmetric, Hickernell; unanchored;
mixture, Zhou, Fang & Ning), each O(N log N) in double-double; star (exact up
to 4096 points, else bounds with their gap); edge (720 directions). Returns
the values of `aapat discrepancy --json` (without its source): points, then
l2_star, l2_generalized, l2_centred, l2_wrap_around, l2_unanchored,
l2_symmetric, l2_mixture, star_lower, star_upper, star_exact (the exact value, or None where only
bounds were computed), star_is_exact, star_gap, edge,
edge_normal_deg (of the measures asked).

Every value is the discrepancy D, not D^2: scipy.stats.qmc.discrepancy returns
CD, WD and MD squared (compare l2_centred**2, l2_wrap_around**2,
l2_mixture**2) and the L2-star not.

    measures: a comma list of "l2-star", "l2-generalized", "l2-centred",
        "l2-wrap-around", "l2-unanchored", "l2-symmetric", "l2-mixture",
        "star", "edge", or "all". The L2 discrepancies take up to 10^7
        points, the others 65,536.)doc");

  m.def(
      "spectrum",
      [](const py::object& source, int n, int size, int realizations, uint64_t seed,
         const std::string& method) {
        if (method != "exact" && method != "fast")
          throw Error(fmt::format("spectrum: method '{}': use 'exact' or 'fast'", method));
        PointSets sets;
        std::string spec;
        if (py::isinstance<py::str>(source))
          spec = source.cast<std::string>();
        else
          sets = to_sets(source);
        if (spec.empty() && sets.empty()) throw Error("spectrum: no point set given");
        if (spec.empty() && realizations != 1 && static_cast<size_t>(realizations) != sets.size())
          throw Error("spectrum: the sets given are the realizations; leave realizations at 1");
        SpectrumSettings s{size, spec.empty() ? static_cast<int>(sets.size()) : realizations,
                           spec.empty() ? 0 : static_cast<size_t>(n), method == "fast"};
        const auto st = interruptible([&] {
          return spectrum_study(
              [&](int r) { return spec.empty() ? sets[r] : generate_points(spec, n, seed + r); },
              s);
        });
        Array power({static_cast<py::ssize_t>(size), static_cast<py::ssize_t>(size)});
        std::copy(st.mean.power.begin(), st.mean.power.end(), power.mutable_data());
        return py::dict(py::arg("power") = power, py::arg("radius") = from_vector(st.radial.radius),
                        py::arg("radial_power") = from_vector(st.radial.power),
                        py::arg("anisotropy_db") = from_vector(st.radial.anisotropy_db),
                        py::arg("points") = st.points, py::arg("realizations") = s.realizations,
                        py::arg("error_bound") = st.error_bound);
      },
      py::arg("source"), py::arg("n") = kDefaultSpectrumPoints,
      py::arg("size") = SpectrumSettings{}.size,
      py::arg("realizations") = SpectrumSettings{}.realizations, py::arg("seed") = 1,
      py::arg("method") = "exact",
      R"doc(The power spectrum P(f) = |sum exp(-2 pi i f.p)|^2 / N of points on the torus.

    source: a generator spec (drawn `realizations` times with seeds seed,
        seed+1, ...), an (n, 2) array, or a list of arrays (averaged).
    n: points per realization of a generator. size: frequencies -size/2 ..
        size/2-1 per axis.
    method: "exact" (the sum, O(N size^2)) or "fast" (a non-uniform FFT,
        O(N + size^2 log size), within error_bound; even sizes).
Returns a dict: power (size x size, row v from -size/2, column u), radius,
radial_power, anisotropy_db (the radial average), points, realizations,
error_bound (on |P - exact P| at every f != 0; 0 for the exact sum).)doc");

  m.def(
      "spectrum_1d",
      [](const std::vector<std::string>& kinds, int n, uint64_t seed, int frequencies,
         double max_frequency) {
        const auto spectra =
            interruptible([&] { return line_spectra(kinds, n, seed, frequencies, max_frequency); });
        py::dict d(py::arg("frequency") =
                       from_vector(line_frequencies(frequencies, max_frequency)));
        for (const LineSpectrum& s : spectra) d[py::str(s.kind)] = from_vector(s.power);
        return d;
      },
      py::arg("kinds"), py::arg("n") = kDefaultLinePoints, py::arg("seed") = 1,
      py::arg("frequencies") = kDefaultLineFrequencies,
      py::arg("max_frequency") = kDefaultLineMaxFrequency,
      R"doc(Goss & Wu Fig. 8: 1D power spectra of n points with unit mean spacing.

    kinds: a list of "poisson" and/or "jittered". Returns a dict: frequency
        (cycles per mean spacing) and one power array per kind.)doc");
}

}  // namespace aapat::python
