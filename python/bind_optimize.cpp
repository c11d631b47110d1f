// The optimizer (family search or polish, with the lattice stage) and the
// enumeration of the P(4,1+,n) placements, the GIL released while they run.
#include <fmt/format.h>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/io/api_export.h"
#include "aapat/study/optimize_run.h"
#include "aapat/study/pattern_studies.h"
#include "aapat/study/study_json.h"
#include "bindings.h"

namespace aapat::python {

std::function<void(int, int, const std::string&)> progress_of(const py::object& callback) {
  if (callback.is_none()) return {};  // Ctrl-C is heard by interruptible()
  if (!PyCallable_Check(callback.ptr()))
    throw Error("progress: give a callable f(done, total, note), or None");
  return [callback](int done, int total, const std::string& note) {
    py::gil_scoped_acquire gil;  // called from the library's worker threads
    callback(done, total, note);
  };
}

namespace {

py::object optional_float(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

py::dict starts_dict(const MultiStartResult& r) {
  std::vector<double> start, initial, final_e2, iterations, seconds;
  for (const StartRecord& s : r.starts) {
    start.push_back(s.start);
    initial.push_back(s.run.initial_e2);
    final_e2.push_back(s.run.final_e2);
    iterations.push_back(s.run.iterations);
    seconds.push_back(s.seconds);
  }
  return py::dict(
      py::arg("start") = from_vector(start), py::arg("initial_e2") = from_vector(initial),
      py::arg("final_e2") = from_vector(final_e2), py::arg("iterations") = from_vector(iterations),
      py::arg("seconds") = from_vector(seconds));
}

py::object lattice_dict(const std::optional<LatticeStage>& L) {
  if (!L) return py::none();
  py::dict d(py::arg("steps") = L->steps, py::arg("profile") = L->profile,
             py::arg("continuous_e2") = L->continuous_e2, py::arg("snapped_e2") = L->snapped_e2,
             py::arg("lattice_e2") = L->lattice_e2, py::arg("starts") = L->starts,
             py::arg("best_start") = L->best_start, py::arg("moves") = L->moves);
  if (L->layout)
    d["layout"] = py::dict(py::arg("grid") = py::make_tuple(L->layout->grid_w, L->layout->grid_h),
                           py::arg("sample_count") = L->layout->sample_count,
                           py::arg("reads") = L->layout->reads());
  return d;
}

OptimizeRunResult run_optimize(const py::object& family, const py::object& pattern,
                               const std::string& placement, const py::object& starts,
                               uint64_t seed, const std::string& seeds, const std::string& method,
                               int iterations, bool weights_only, bool nonnegative,
                               const std::vector<int>& lock, int lattice, const std::string& api,
                               int threads, double time_limit, bool border_samples,
                               const Objective& objective, const py::object& progress) {
  OptimizeRunSettings s;
  if (!family.is_none()) s.family = family.cast<std::string>();
  if (!pattern.is_none()) {
    s.start = to_pattern(pattern);
    s.start_label = py::isinstance<py::str>(pattern) ? pattern.cast<std::string>() : s.start->name;
  }
  check_family_or_pattern(!s.family.empty(), s.start.has_value());
  s.placement = placement;
  if (!starts.is_none()) s.starts = starts.cast<int>();
  s.seed = seed;
  s.seeds = seeds;
  s.lock = lock;
  s.strictly_inside = !border_samples;
  s.threads = threads;
  s.lattice = lattice;
  s.api = api;
  s.optimizer.method = parse_method(method);
  s.optimizer.max_iterations = iterations;
  s.optimizer.weights_only = weights_only;
  s.optimizer.nonnegative_weights = nonnegative;
  s.time_limit = time_limit;
  const auto report = progress_of(progress);
  return interruptible([&] { return optimize_run(objective, s, report); });
}

}  // namespace

void bind_optimize(py::module_& m) {
  py::class_<OptimizeRunResult>(m, "OptimizeResult", "What aapat.optimize found.")
      .def_readonly("pattern", &OptimizeRunResult::best, "the best pattern, with its provenance")
      .def_property_readonly(
          "e2", [](const OptimizeRunResult& r) { return r.best_start().run.final_e2; },
          "its E2 (before a lattice stage; the lattice's is in .lattice)")
      .def_property_readonly(
          "initial_e2", [](const OptimizeRunResult& r) { return r.best_start().run.initial_e2; })
      .def_property_readonly("best_start",
                             [](const OptimizeRunResult& r) { return r.best_start().start; })
      .def_property_readonly(
          "iterations", [](const OptimizeRunResult& r) { return r.best_start().run.iterations; })
      .def_property_readonly(
          "report", [](const OptimizeRunResult& r) { return to_python(optimize_run_json(r)); },
          "the result as `aapat optimize --json` prints it: the same keys and values")
      .def_property_readonly(
          "objective", [](const OptimizeRunResult& r) { return r.objective.text(); },
          "the objective its E2 is under")
      .def_readonly("description", &OptimizeRunResult::description)
      .def_readonly("placement", &OptimizeRunResult::placement)
      .def_readonly("method", &OptimizeRunResult::method)
      .def_readonly("seconds", &OptimizeRunResult::seconds)
      .def_property_readonly(
          "starts", [](const OptimizeRunResult& r) { return starts_dict(r.search); },
          "every start: arrays start, initial_e2, final_e2, iterations, seconds")
      .def_property_readonly("lattice",
                             [](const OptimizeRunResult& r) { return lattice_dict(r.lattice); })
      .def_property_readonly(
          "unconstrained_e2",
          [](const OptimizeRunResult& r) { return optional_float(r.unconstrained_e2); },
          "with nonnegative=True: the same best start without the constraint")
      .def("__repr__", [](const OptimizeRunResult& r) {
        return fmt::format("<aapat.OptimizeResult {}: E2 {:.4f}>", r.description,
                           r.best_start().run.final_e2);
      });

  m.def(
      "optimize",
      [](const py::object& family, const py::object& pattern, const std::string& placement,
         const py::object& starts, uint64_t seed, const std::string& seeds,
         const std::string& method, int iterations, bool weights_only, bool nonnegative,
         const std::vector<int>& lock, int lattice, const std::string& api, int threads,
         double time_limit, bool border_samples, const py::object& progress,
         const py::object& objective, const py::object& filter, const py::object& acuity,
         const py::object& norm) {
        return run_optimize(family, pattern, placement, starts, seed, seeds, method, iterations,
                            weights_only, nonnegative, lock, lattice, api, threads, time_limit,
                            border_samples, make_objective(objective, filter, acuity, norm),
                            progress);
      },
      py::kw_only(), py::arg("family") = py::none(), py::arg("pattern") = py::none(),
      // The defaults are the library's (a default-constructed OptimizeRunSettings).
      py::arg("placement") = "", py::arg("starts") = py::none(),
      py::arg("seed") = OptimizeRunSettings{}.seed, py::arg("seeds") = OptimizeRunSettings{}.seeds,
      py::arg("method") = method_key(OptimizerSettings{}.method),
      py::arg("iterations") = OptimizerSettings{}.max_iterations,
      py::arg("weights_only") = OptimizerSettings{}.weights_only,
      py::arg("nonnegative") = OptimizerSettings{}.nonnegative_weights,
      py::arg("lock") = std::vector<int>{}, py::arg("lattice") = OptimizeRunSettings{}.lattice,
      py::arg("api") = "", py::arg("threads") = OptimizeRunSettings{}.threads,
      py::arg("time_limit") = OptimizeRunSettings{}.time_limit,
      py::arg("border_samples") = !OptimizeRunSettings{}.strictly_inside,
      py::arg("progress") = py::none(), AAPAT_OBJECTIVE_ARGS,
      with_metric_args(
          R"doc(Optimize positions and weights: a family from random starts, or a pattern.

The same run as `aapat optimize`, with the same result for the same seed (any
thread count). Returns an aapat.OptimizeResult (.pattern, .e2, .starts, ...).

    family: the family to search, e.g. "P(4,1+,2)" (Laine-Aila Sec. 5).
    pattern: instead, a pattern to polish (catalog name, file or aapat.Pattern);
        start 0 is the pattern itself, later starts jitter it by 0.1 pixel.
    placement: sites of the base pixel's samples: inside, left, right, bottom,
        top, bottom-left, ... (FLIPQUAD: "left,right,bottom,top"); empty for a
        P(4,1+,n) family: every placement of its cost is searched.
    starts: random starts, run in parallel (default 16; 1 when polishing).
    seed: random seed. seeds: seed patterns, "jittered", "poisson" or "uniform".
    method: "descent" (Laine-Aila heuristic), "minimax" (eps-active min-norm
        descent), "anneal", or the epigraph form with NLopt: "slsqp", "mma", "ccsaq". iterations: per start at most (default 4000).
    weights_only: keep positions, optimize weights (Opt W).
    nonnegative: keep weights >= 0 (and report the E2 this costs).
    lock: samples of the base pixel (set 0) to keep fixed.
    lattice: then search positions on the 1/N-pixel lattice (16: programmable
        MSAA). api: with the lattice, the API profile the pattern must fit
        ("d3d12-tier1", "d3d12-tier2", "vulkan", "metal", "gl").
    threads: 0 for all cores. time_limit: seconds for the whole run (0: none).
    border_samples: let samples of a family without shared borders onto the
        pixel's border (the papers' closed pixel); default strictly inside.
    progress: a callable f(done, total, note), called as starts finish.)doc"));

  m.def(
      "enumerate",
      [](const std::vector<double>& costs, int max_per_edge, bool cull_one_edge, bool optimize,
         int starts, uint64_t seed, const py::object& progress, const py::object& objective,
         const py::object& filter, const py::object& acuity, const py::object& norm) {
        const Objective o = make_objective(objective, filter, acuity, norm);
        EnumerationSettings s;
        s.costs = costs;
        s.rules = {max_per_edge, cull_one_edge};
        s.optimize = optimize;
        s.starts = starts;
        s.seed = seed;
        const auto report = progress_of(progress);
        const auto e = interruptible([&] { return enumerate_study(o.metric(), s, report); });
        // The rows of `aapat enumerate --json`, each with its best pattern.
        py::list rows = rows_of(enumeration_json(o, s, e));
        for (size_t i = 0; i < e.rows.size(); ++i)
          rows[i]["pattern"] = optimize ? py::cast(e.rows[i].best) : py::object(py::none());
        return rows;
      },
      py::kw_only(), py::arg("costs") = EnumerationSettings{}.costs,
      py::arg("max_per_edge") = EnumerationSettings{}.rules.max_per_edge,
      py::arg("cull_one_edge") = EnumerationSettings{}.rules.cull_one_edge,
      py::arg("optimize") = EnumerationSettings{}.optimize,
      py::arg("starts") = EnumerationSettings{}.starts,
      py::arg("seed") = EnumerationSettings{}.seed, py::arg("progress") = py::none(),
      AAPAT_OBJECTIVE_ARGS,
      with_metric_args(
          R"doc(Every placement configuration of the mirrored P(4,1+,n) family (Hasselgren Sec. 5).

The rows of `aapat enumerate --json`, each with its best pattern: a list of
dicts {id, n, placement, samples_read, e2, pattern}, ranked
by E2 within each cost when optimized (e2 and pattern are None otherwise).

    costs: costs n, multiples of 1/4. max_per_edge: samples one edge may hold.
    cull_one_edge: drop configurations with every sample on one border line.
    optimize: optimize every configuration from `starts` jittered starts.
    seed: random seed. progress: a callable f(done, total, note).)doc"));

  m.def(
      "snap",
      [](const py::object& pattern, int lattice, bool optimize_weights, bool nonnegative,
         const py::object& objective, const py::object& filter, const py::object& acuity,
         const py::object& norm) {
        if (nonnegative && !optimize_weights)
          throw Error(
              "nonnegative constrains the weights optimize_weights finds: set optimize_weights");
        const Objective o = make_objective(objective, filter, acuity, norm);
        const Pattern before = to_pattern(pattern);
        const SnapResult r = interruptible(
            [&] { return snap_study(o.metric(), before, lattice, optimize_weights, nonnegative); });
        py::dict d = to_python(snap_json(o, before.name, lattice, r));
        d["result"] = r.snapped;
        return d;
      },
      py::arg("pattern"), py::kw_only(), py::arg("lattice") = kLatticeSteps,
      py::arg("optimize_weights") = false, py::arg("nonnegative") = false, AAPAT_OBJECTIVE_ARGS,
      R"doc(aapat snap: every sample to the nearest point of the 1/lattice-pixel lattice
(programmable MSAA's 1/16), E2 before and after, and with optimize_weights the
weights re-optimized for the snapped positions (nonnegative: weights >= 0). A
dict with the values of `aapat snap --json`; "result" is the snapped
aapat.Pattern.)doc");

  m.def(
      "export",
      [](const py::object& pattern, const std::string& api, const std::string& shader, bool snap,
         const std::optional<std::pair<int, int>>& grid, const py::object& objective,
         const py::object& filter, const py::object& acuity, const py::object& norm) {
        const ApiProfile& profile = api_profile(api);
        const Objective o = make_objective(objective, filter, acuity, norm);
        int gw = 0, gh = 0;
        if (grid) {
          std::tie(gw, gh) = *grid;
          check_export_grid(profile, gw, gh, "grid");
        }
        return export_pattern(
            to_pattern(pattern), profile, o,
            shader.empty() ? default_shader(profile) : parse_shader_language(shader), snap, gw, gh);
      },
      py::arg("pattern"), py::kw_only(), py::arg("api") = "d3d12-tier1", py::arg("shader") = "",
      py::arg("snap") = false, py::arg("grid") = py::none(), AAPAT_OBJECTIVE_ARGS,
      R"doc(aapat export: a lattice pattern as an API's sample positions and a resolve
shader, the text `aapat export` prints. api: "d3d12-tier1", "d3d12-tier2",
"vulkan", "metal" or "gl"; shader: "hlsl", "glsl" or "msl" (default the API's
own); snap: snap to the 1/16 lattice first; grid: (w, h) pixels for the APIs
that take a grid (default the pattern's tile).)doc");
}

}  // namespace aapat::python
