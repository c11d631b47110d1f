// The papers' experiments re-run: Laine-Aila Table 3 and Figure 10,
// Hasselgren Table 2, the hardware lattice table.
#include "aapat/study/paper_tables.h"
#include "aapat/study/pattern_studies.h"
#include "bindings.h"

namespace aapat::python {

void bind_studies(py::module_& m) {
  m.def(
      "table3",
      [](int patterns, int iterations, uint64_t seed, const py::object& objective,
         const py::object& filter, const py::object& acuity, const py::object& norm) {
        const Metric metric = make_metric(objective, filter, acuity, norm);
        std::vector<Table3Row> rows;
        {
          py::gil_scoped_release release;
          rows = table3(metric, {patterns, iterations, seed});
        }
        py::list l;
        for (const Table3Row& r : rows)
          l.append(py::dict(py::arg("distribution") = r.distribution, py::arg("min") = r.e2[0],
                            py::arg("avg") = r.e2[1], py::arg("max") = r.e2[2],
                            py::arg("opt_w") = r.e2[3], py::arg("opt_wp") = r.e2[4],
                            py::arg("paper") = r.paper));
        return l;
      },
      py::kw_only(), py::arg("patterns") = Table3Settings{}.patterns,
      py::arg("iterations") = Table3Settings{}.iterations, py::arg("seed") = Table3Settings{}.seed,
      py::arg("objective") = std::string(kPapersObjective), py::arg("filter") = py::none(),
      py::arg("acuity") = py::none(), py::arg("norm") = py::none(),
      with_metric_args(
          R"doc(Laine-Aila Table 3: P(16,16,4) jittered and Poisson patterns, min/avg/max E2,
then the best optimized for weights (opt_w) and positions (opt_wp). A list of
dicts with the paper's five numbers beside.)doc"));

  m.def(
      "figure10",
      [](int starts, uint64_t seed, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        const Metric metric = make_metric(objective, filter, acuity, norm);
        Figure10 fig;
        {
          py::gil_scoped_release release;
          fig = figure10(metric, {starts, seed});
        }
        py::list l;
        for (const Figure10Point& p : fig.points)
          l.append(py::dict(py::arg("family") = p.family, py::arg("n") = p.n, py::arg("e2") = p.e2,
                            py::arg("placement") = p.placement,
                            py::arg("series") = fig.series[p.series]));
        return l;
      },
      py::kw_only(), py::arg("starts") = Figure10Settings{}.starts,
      py::arg("seed") = Figure10Settings{}.seed,
      py::arg("objective") = std::string(kPapersObjective), py::arg("filter") = py::none(),
      py::arg("acuity") = py::none(), py::arg("norm") = py::none(),
      with_metric_args(
          R"doc(Laine-Aila Figure 10: the best E2 of P(1,1,n), P(4,1+,n), P(1,4,n), P(4,4,n)
against n. A list of dicts {family, n, e2, placement, series}.)doc"));

  m.def(
      "table2",
      [](int size, int frames) {
        AnimationSettings a;
        a.width = a.height = size;
        a.frames = frames;
        std::vector<Table2Row> rows;
        {
          py::gil_scoped_release release;
          rows = table2(a);
        }
        py::list l;
        for (const Table2Row& r : rows)
          l.append(py::dict(py::arg("pattern") = r.pattern, py::arg("label") = r.label,
                            py::arg("e2") = r.e2, py::arg("rmse") = r.rmse,
                            py::arg("max_deviation") = r.max_deviation,
                            py::arg("paper_e2") = r.paper_e2, py::arg("paper_rmse") = r.paper_rmse,
                            py::arg("paper_max_deviation") = r.paper_max_deviation));
        return l;
      },
      py::kw_only(), py::arg("size") = 64, py::arg("frames") = 32,
      R"doc(Hasselgren Table 2 re-measured: E2, RMSE and max deviation of the nine patterns
on the translating circle (size x size, `frames` frames, 256-sample reference).)doc");

  m.def(
      "hardware_table",
      [](int starts, uint64_t seed, const py::object& objective, const py::object& filter,
         const py::object& acuity, const py::object& norm) {
        const Metric metric = make_metric(objective, filter, acuity, norm);
        std::vector<HardwareTableRow> rows;
        {
          py::gil_scoped_release release;
          rows = hardware_table(metric, {starts, seed});
        }
        py::list l;
        for (const HardwareTableRow& r : rows)
          l.append(py::dict(py::arg("n") = r.n, py::arg("pattern") = r.pattern,
                            py::arg("profile") = r.profile, py::arg("layout") = r.layout,
                            py::arg("e2_continuous") = r.continuous_e2,
                            py::arg("e2_lattice") = r.lattice_e2));
        return l;
      },
      py::kw_only(), py::arg("starts") = HardwareTableSettings{}.starts,
      py::arg("seed") = HardwareTableSettings{}.seed, AAPAT_OBJECTIVE_ARGS,
      with_metric_args(
          R"doc(What the APIs' 1/16-pixel lattice costs: standard and optimized patterns at 2,
4, 8 and 16 samples, and the sharing schemes, continuous and on the lattice.)doc"));
}

}  // namespace aapat::python
