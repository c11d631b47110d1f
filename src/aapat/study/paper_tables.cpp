#include "aapat/study/paper_tables.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>

#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/generate/catalog.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/lattice_search.h"
#include "aapat/optimize/multistart.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/work_items.h"

namespace aapat {
namespace {

void check_count(int value, int limit, const char* parameter) {
  if (!(value >= 1 && value <= limit))
    throw ParameterError(parameter, fmt::format(" {}: expected 1 to {}", value, limit));
}

// One distribution's row of Table 3.
Table3Row table3_row(const Metric& metric, const Table3Settings& s, const char* name, SeedKind kind,
                     std::array<double, 5> paper, const StudyProgress& progress) {
  const FamilySpec spec = parse_family("P(16,16,4)", "");
  // Pattern i is drawn from start_rng(seed, i) alone: evaluated in parallel,
  // then summed and compared in index order, the same for any thread count.
  auto draw = [&](int i) {
    auto rng = start_rng(s.seed, static_cast<uint64_t>(i));
    return seed_pattern(spec, kind, rng, metric.filter());  // h(x) h(y) weights
  };
  std::vector<double> e2(static_cast<size_t>(s.patterns));
  std::atomic<int> done{0};
  tbb::parallel_for(0, s.patterns, [&](int i) {
    e2[static_cast<size_t>(i)] = metric.evaluate(draw(i)).e2;
    const int finished = ++done;
    if (progress && (finished % 50 == 0 || finished == s.patterns))
      progress(finished, s.patterns, name);  // the caller's progress is thread-safe
  });
  double lo = INFINITY, hi = 0, sum = 0;
  int best_index = 0;
  for (int i = 0; i < s.patterns; ++i) {
    sum += e2[static_cast<size_t>(i)];
    hi = std::max(hi, e2[static_cast<size_t>(i)]);
    if (e2[static_cast<size_t>(i)] < lo) lo = e2[static_cast<size_t>(i)], best_index = i;
  }
  const Pattern best = draw(best_index);
  OptimizerSettings settings;
  settings.max_iterations = s.iterations;
  settings.weights_only = true;
  const MultiStartResult w = multistart(
      metric, 1, s.seed, [&](int) { return problem_from_pattern(best); }, settings, 0);
  settings.weights_only = false;
  settings.method = s.method;
  const Problem after_w = w.best_problem;
  const MultiStartResult wp = multistart(
      metric, 1, s.seed, [&](int) { return after_w; }, settings, 0);
  return {
      name,
      {lo, sum / s.patterns, hi, w.starts[w.best].run.final_e2, wp.starts[wp.best].run.final_e2},
      paper};
}

std::string layout_text(const Pattern& p, const ApiProfile& profile) {
  const HardwareLayout L = hardware_layout(p, profile);
  return fmt::format("{}x{} grid, {}x MSAA, reads {}", L.grid_w, L.grid_h, L.sample_count,
                     format_cost(L.reads()));
}

struct Figures {
  double continuous = 0, lattice = 0;
  std::string layout;
};

// A pattern snapped, its weights optimized, then searched on the lattice from there.
Figures snapped(const Metric& metric, const Pattern& p, const ApiProfile& profile) {
  Problem problem = problem_from_pattern(snap_to_lattice(p, kLatticeSteps));
  const LatticeRun run = lattice_descent(metric, problem, kLatticeSteps, OptimizerSettings{});
  return {metric.evaluate(p).e2, run.final_e2, layout_text(pattern_of(problem), profile)};
}

}  // namespace

std::vector<Table3Row> table3(const Metric& metric, const Table3Settings& settings,
                              const StudyProgress& progress) {
  check_count(settings.patterns, 1000000, "patterns");
  check_count(settings.iterations, 10000000, "iterations");
  // The two distributions as two work items (work/work_items.h), at once:
  // each row's optimizations run one start each, so the rows are the
  // parallelism there is (docs/benchmarks.md).
  std::mutex report;
  const StudyProgress locked = [&](int done, int total, const std::string& note) {
    if (!progress) return;
    std::lock_guard<std::mutex> lock(report);
    progress(done, total, note);
  };
  const std::array<const char*, 2> names = {"jittered grid", "Poisson disk"};
  const std::array<SeedKind, 2> kinds = {SeedKind::kJittered, SeedKind::kPoisson};
  const std::array<std::array<double, 5>, 2> papers = {
      std::array<double, 5>{0.423, 0.622, 0.907, 0.242, 0.169},
      std::array<double, 5>{0.346, 0.473, 0.782, 0.221, 0.161}};
  const std::vector<std::string> results = run_work_items(2, [&](int i) {
    const Table3Row row = table3_row(metric, settings, names[i], kinds[i], papers[i], locked);
    ByteWriter w;
    for (double e2 : row.e2) w.put(e2);
    return w.take();
  });
  std::vector<Table3Row> rows;
  for (int i = 0; i < 2; ++i) {
    ByteReader r(results[static_cast<size_t>(i)]);
    Table3Row row{names[i], {}, papers[i]};
    for (double& e2 : row.e2) e2 = r.get<double>();
    r.finish();
    rows.push_back(row);
  }
  return rows;
}

// The structures of Hasselgren's schemes A-F below n = 2, FLIPQUAD's edges
// plus inside samples above.
std::vector<std::string> figure10_placements(double n) {
  if (n == 1.25) return {"top-left,bottom,right"};
  if (n == 1.5) return {"left,bottom,top", "left,bottom-left,top,bottom-right"};
  if (n == 1.75) return {"bottom-left,inside,right", "bottom-left,left,top,right"};
  if (n == 2)
    return {"left,right,bottom,top", "inside,bottom-left,bottom-right,top-left,top-right"};
  std::string edges = "left,right,bottom,top", inside;
  for (int i = 0; i < n - 2; ++i) edges += ",inside";
  for (int i = 0; i < n; ++i) inside += i ? ",inside" : "inside";
  return {edges, inside};
}

Figure10 figure10(const Metric& metric, const Figure10Settings& settings,
                  const StudyProgress& progress) {
  check_count(settings.starts, 100000, "starts");
  Figure10 fig;
  const std::vector<std::string> families = {"P(1,1,{})", "P(4,1+,{})", "P(1,4,{})", "P(4,4,{})"};
  // Every (family, n, placement) search at once (multistart_all): their
  // starts are one set of work items, the best per (family, n) taken after.
  struct Search {
    Figure10Point point;  // family, placement, n, series
    size_t point_index;   // into fig.points
  };
  std::vector<Search> searches;
  std::vector<MultiStartJob> jobs;
  for (const auto& f : families) {
    const bool mirrored = f == "P(4,1+,{})";
    fig.series.push_back(fmt::vformat(f, fmt::make_format_args("n")));
    std::vector<double> ns = {2, 3, 4, 5, 6};
    if (mirrored) ns.insert(ns.begin(), {1.25, 1.5, 1.75});
    for (double n : ns) {
      const std::string fam = fmt::vformat(f, fmt::make_format_args(format_cost(n)));
      const int series = static_cast<int>(fig.series.size()) - 1;
      fig.points.push_back({fam, "", n, INFINITY, series});
      for (const auto& placement :
           mirrored ? figure10_placements(n) : std::vector<std::string>{""}) {
        const FamilySpec spec = parse_family(fam, placement);
        searches.push_back({{fam, placement, n, INFINITY, series}, fig.points.size() - 1});
        jobs.push_back({&metric, settings.starts, settings.seed,
                        family_seeds(spec, SeedKind::kJittered, settings.seed, metric.filter()),
                        OptimizerSettings{}});
      }
    }
  }
  const std::vector<MultiStartResult> results =
      multistart_all(jobs, [&](int done, int total, double best) {
        if (progress) progress(done, total, fmt::format("best E2 {:.4f}", best));
      });
  for (size_t k = 0; k < searches.size(); ++k) {
    const MultiStartResult& r = results[k];
    Figure10Point point = searches[k].point;
    point.e2 = r.starts[r.best].run.final_e2;
    Figure10Point& best = fig.points[searches[k].point_index];
    if (point.e2 < best.e2) best = point;
  }
  return fig;
}

std::vector<HardwareTableRow> hardware_table(const Metric& metric,
                                             const HardwareTableSettings& settings,
                                             const StudyProgress& progress) {
  check_count(settings.starts, 100000, "starts");
  const ApiProfile &tier1 = api_profile("d3d12-tier1"), &tier2 = api_profile("d3d12-tier2");
  const std::vector<int> counts = {2, 4, 8, 16};
  const std::vector<std::string> hasselgren = {"hasselgren-a",       "hasselgren-b", "hasselgren-c",
                                               "hasselgren-d",       "hasselgren-e", "hasselgren-f",
                                               "quincunx-hasselgren"};
  int done = 0;
  const int total = 4 * 3 + 2 + 7;
  auto report = [&](int step, const std::string& note) {
    done += step;
    if (progress) progress(done, total, note);
  };
  // The searches, all their starts as one set of work items (multistart_all),
  // then each one's lattice search: P(1,1,n) on tier 1, P(4,4,n) on tier 2.
  std::vector<std::string> families;
  std::vector<const ApiProfile*> profiles;
  for (int n : counts) {
    families.push_back(fmt::format("P(1,1,{})", n));
    profiles.push_back(&tier1);
    if (n <= 4) {
      families.push_back(fmt::format("P(4,4,{})", n));
      profiles.push_back(&tier2);
    }
  }
  std::vector<SeedFunction> seeds;
  std::vector<MultiStartJob> jobs;
  for (const std::string& family : families) {
    seeds.push_back(family_seeds(parse_family(family, ""), SeedKind::kJittered, settings.seed,
                                 metric.filter()));
    jobs.push_back({&metric, settings.starts, settings.seed, seeds.back(), OptimizerSettings{}});
  }
  const std::vector<MultiStartResult> found = multistart_all(jobs);
  std::map<std::string, Figures> searched;
  for (size_t k = 0; k < families.size(); ++k) {
    const MultiStartResult& r = found[k];
    const LatticeSearch lat =
        lattice_search_from(metric, r.best_problem, seeds[k], settings.starts, settings.seed,
                            kLatticeSteps, OptimizerSettings{});
    searched[families[k]] = {r.starts[r.best].run.final_e2, lat.run.final_e2,
                             layout_text(pattern_of(lat.best), *profiles[k])};
    report(1, families[k]);
  }
  // The standard and Hasselgren's patterns snapped and descended on the
  // lattice, one work item each.
  std::vector<std::string> names;
  for (int n : counts) names.push_back(fmt::format("msaa-{}", n));
  names.insert(names.end(), hasselgren.begin(), hasselgren.end());
  const auto profile_of = [&](const Pattern& p) -> const ApiProfile& {
    return p.tile_w == 1 ? tier1 : tier2;
  };
  const std::vector<std::string> snaps = run_work_items(static_cast<int>(names.size()), [&](int k) {
    const Pattern p = catalog_pattern(names[static_cast<size_t>(k)]);
    const Figures f = snapped(metric, p, profile_of(p));
    ByteWriter w;
    w.put(f.continuous).put(f.lattice).put_text(f.layout);
    return w.take();
  });
  std::map<std::string, Figures> snapped_figures;
  for (size_t k = 0; k < names.size(); ++k) {
    ByteReader r(snaps[k]);
    Figures& f = snapped_figures[names[k]];
    f.continuous = r.get<double>();
    f.lattice = r.get<double>();
    f.layout = r.get_text();
    r.finish();
  }

  std::vector<HardwareTableRow> rows;
  auto row = [&](const std::string& n, const std::string& what, const ApiProfile& profile,
                 const Figures& f) {
    rows.push_back({n, what, profile.name, f.layout, f.continuous, f.lattice});
  };
  for (int n : counts) {
    const std::string count = std::to_string(n);
    const Pattern msaa = catalog_pattern(fmt::format("msaa-{}", n));
    const double box = metric.evaluate(msaa).e2;
    row(count, fmt::format("msaa-{} (standard), box resolve", n), tier1,
        {box, box, layout_text(msaa, tier1)});
    const double w = metric.evaluate(with_optimized_weights(metric, msaa, false)).e2;
    row(count, fmt::format("msaa-{} positions, optimized weights", n), tier1,
        {w, w, layout_text(msaa, tier1)});
    report(2, fmt::format("msaa-{}", n));
    // The search's local optima, or the standard pattern polished on the lattice.
    Figures best = searched.at(fmt::format("P(1,1,{})", n));
    const Figures& polished = snapped_figures.at(fmt::format("msaa-{}", n));
    const bool from_standard = polished.lattice < best.lattice;
    if (from_standard) best.lattice = polished.lattice;
    row(count,
        fmt::format("best P(1,1,{}){}", n,
                    from_standard ? " (msaa-" + count + " polished on the lattice)" : ""),
        tier1, best);
    if (n <= 4)
      row(count, fmt::format("best P(4,4,{}) (2x2-pixel kernels)", n), tier2,
          searched.at(fmt::format("P(4,4,{})", n)));
  }
  for (const std::string& name : hasselgren) {
    const Pattern p = catalog_pattern(name);
    row(format_cost(samples_per_pixel(p)), fmt::format("{} snapped, then searched", name),
        profile_of(p), snapped_figures.at(name));
    report(1, name);
  }
  return rows;
}

}  // namespace aapat
