#include "aapat/study/optimize_run.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "aapat/core/lattice.h"
#include "aapat/core/spec.h"
#include "aapat/generate/enumerate.h"
#include "aapat/io/pattern_json.h"
#include "aapat/optimize/lattice_search.h"
#include "aapat/work/work_items.h"

namespace aapat {

void check_family_or_pattern(bool has_family, bool has_pattern) {
  if (has_family == has_pattern)
    throw Error("optimize: give either a family (a search) or a pattern (to polish), not both");
}

namespace {

// Start 0 is the pattern itself; later starts jitter it by up to 0.1 pixel.
SeedFunction polish_seeds(const Problem& start, uint64_t seed) {
  return [start, seed](int i) {
    if (i == 0) return start;
    auto rng = start_rng(seed, static_cast<uint64_t>(i));
    return perturbed(start, 0.1, rng);
  };
}

// Locked samples, and every free sample of a family without shared borders
// strictly inside the pixel (problem.h: keep_strictly_inside).
SeedFunction constrained(SeedFunction seeds, std::vector<int> lock, bool strictly_inside) {
  return [seeds = std::move(seeds), lock = std::move(lock), strictly_inside](int i) {
    Problem p = seeds(i);
    lock_samples(p, lock);
    if (strictly_inside) keep_strictly_inside(p);
    return p;
  };
}

// The placements a family search tries: the one given or, for a sharing
// family without one, every placement of its cost (as the enumeration lists
// them); otherwise every sample would sit inside and nothing would be shared.
std::vector<std::string> placements_of(const OptimizeRunSettings& s) {
  const FamilySpec spec = family_shape(s.family);
  if (!spec.mirrored || !s.placement.empty()) return {s.placement};
  std::vector<std::string> all;
  for (const PlacementConfig& c : enumerate_placements(spec.n)) all.push_back(c.sites());
  return all;
}

// From the continuous optimum, kicks around it, and fresh seeds, all snapped.
LatticeStage lattice_stage(const Metric& metric, const OptimizeRunSettings& s,
                           MultiStartResult& result, const SeedFunction& make_seed, int starts,
                           const StudyProgress& progress) {
  const ApiProfile* profile = s.api.empty() ? nullptr : &api_profile(s.api);
  LatticeStage stage;
  stage.steps = s.lattice;
  if (profile) {
    stage.profile = profile->name;
    // Fails early, naming the reason, if the family cannot fit the profile.
    hardware_layout(snap_to_lattice(pattern_of(make_seed(0)), s.lattice, profile->y_down),
                    *profile);
  }
  const LatticeSearch lat =
      lattice_search_from(metric, result.best_problem, make_seed, starts, s.seed, s.lattice,
                          s.optimizer, profile ? profile->y_down : true, progress);
  result.best_problem = lat.best;
  stage.continuous_e2 = result.starts[result.best].run.final_e2;
  stage.snapped_e2 = lat.run.snapped_e2;
  stage.lattice_e2 = lat.run.final_e2;
  stage.starts = lat.starts;
  stage.best_start = lat.best_start;
  stage.moves = lat.run.moves;
  if (profile) stage.layout = hardware_layout(pattern_of(lat.best), *profile);
  return stage;
}

void check_settings(const OptimizeRunSettings& s) {
  if (s.family.empty() && !s.start) check_family_or_pattern(false, false);
  if (s.starts && !(*s.starts >= 1 && *s.starts <= kMaxStarts))
    throw Error(fmt::format("optimize: starts {} is not in [1, {}]", *s.starts, kMaxStarts));
  if (!(s.time_limit >= 0 && std::isfinite(s.time_limit)))
    throw Error(fmt::format("optimize: time limit {} is not a finite number of seconds >= 0",
                            s.time_limit));
  if (s.optimizer.max_iterations < 1 || s.optimizer.max_iterations > kMaxIterations)
    throw Error(fmt::format("optimize: iterations {} is not in [1, {}]", s.optimizer.max_iterations,
                            kMaxIterations));
  check_threads(s.threads, "optimize: threads");
  if (s.lattice != 0 && !(s.lattice >= kMinLatticeSteps && s.lattice <= kMaxLatticeSteps))
    throw Error(fmt::format("optimize: lattice {} is not in [{}, {}] steps per pixel", s.lattice,
                            kMinLatticeSteps, kMaxLatticeSteps));
  if (!s.api.empty() && s.lattice != kLatticeSteps)
    throw Error(fmt::format("optimize: the API profile {} has a 1/{} pixel lattice, not 1/{}",
                            s.api, kLatticeSteps, s.lattice));
  if (!s.family.empty() && s.start &&
      family(*s.start) != parse_family(s.family, s.placement).text())
    throw Error(fmt::format("optimize: the start pattern {} is {}, not the family {}",
                            s.start_label.empty() ? s.start->name : s.start_label, family(*s.start),
                            s.family));
}

}  // namespace

namespace {

// Each method: the name parse_method reads, and what the provenance calls it.
struct MethodText {
  Method method;
  const char* key;
  const char* name;
};
constexpr MethodText kMethods[] = {
    {Method::kDescent, "descent", "Laine-Aila heuristic (t 0.99, c1 = 100 c0)"},
    {Method::kMinimax, "minimax", "eps-active minimum-norm descent"},
    {Method::kAnneal, "anneal", "simulated annealing"},
    {Method::kSlsqp, "slsqp", "epigraph form, NLopt SLSQP"},
    {Method::kMma, "mma", "epigraph form, NLopt MMA"},
    {Method::kCcsaq, "ccsaq", "epigraph form, NLopt CCSAQ"}};

const MethodText& text_of(Method m) {
  for (const MethodText& t : kMethods)
    if (t.method == m) return t;
  return kMethods[0];
}

}  // namespace

std::string method_name(Method m) {
  return text_of(m).name;
}

std::string method_key(Method m) {
  return text_of(m).key;
}

std::string method_help() {
  std::string text;
  for (const MethodText& t : kMethods)
    text += fmt::format("{}{} ({})", text.empty() ? "" : ", ", t.key, t.name);
  return text;
}

Method parse_method(std::string_view name) {
  std::string keys;
  for (const MethodText& t : kMethods) {
    if (name == t.key) return t.method;
    keys += keys.empty() ? t.key : fmt::format(", {}", t.key);
  }
  throw_unknown_spec("method", name, keys);
}

OptimizeRunResult optimize_run(const Metric& metric, const OptimizeRunSettings& settings,
                               const StudyProgress& progress) {
  OptimizeRunSettings s = settings;
  if (!s.api.empty() && s.lattice == 0) s.lattice = kLatticeSteps;
  check_settings(s);
  if (s.time_limit > 0)
    s.optimizer.deadline = std::chrono::steady_clock::now() +
                           std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               std::chrono::duration<double>(s.time_limit));
  const bool polish = s.start.has_value();
  const int starts = s.starts.value_or(polish ? 1 : kDefaultSearchStarts);
  OptimizeRunResult out;
  out.settings = s;
  out.objective = objective_of(metric);
  out.method = method_name(s.optimizer.method);
  const std::vector<std::string> placements =
      polish ? std::vector<std::string>{s.placement} : placements_of(s);
  const int total = starts * static_cast<int>(placements.size());
  int before = 0;
  auto report = [&](int done, int, double best) {
    if (progress) progress(before + done, total, fmt::format("best E2 {:.4f}", best));
  };

  const auto t0 = std::chrono::steady_clock::now();
  SeedFunction make_seed;
  if (polish) {
    Problem start = problem_from_pattern(*s.start);
    lock_samples(start, s.lock);
    if (s.strictly_inside) keep_strictly_inside(start);
    make_seed = polish_seeds(start, s.seed);
    out.search = multistart(metric, starts, s.seed, make_seed, s.optimizer, s.threads, report);
    out.placement = s.placement;
    out.description = fmt::format("{} {} ({} start{})", start.layout.name, family(start.layout),
                                  starts, starts == 1 ? "" : "s");
  } else {
    const SeedKind kind = parse_seed_kind(s.seeds);
    for (const std::string& placement : placements) {
      const FamilySpec spec = parse_family(s.family, placement);
      SeedFunction seeds =
          constrained(family_seeds(spec, kind, s.seed, metric.filter()), s.lock, s.strictly_inside);
      MultiStartResult r =
          multistart(metric, starts, s.seed, seeds, s.optimizer, s.threads, report);
      before += starts;
      const MultiStartResult& b = out.search;
      if (r.best >= 0 &&
          (b.best < 0 || r.starts[r.best].run.final_e2 < b.starts[b.best].run.final_e2)) {
        out.search = std::move(r);
        make_seed = std::move(seeds);
        out.placement = placement;
      }
    }
    const std::string family_text = parse_family(s.family, out.placement).text();
    out.description =
        placements.size() > 1
            ? fmt::format("{} from {} {} starts for each of its {} placements (best: {})",
                          family_text, starts, s.seeds, placements.size(), out.placement)
            : fmt::format("{} from {} {} starts", family_text, starts, s.seeds);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (out.search.best < 0) throw Error("optimize: the time limit passed before any start ran");
  const StartRecord& best = out.best_start();

  if (s.lattice > 0)
    out.lattice = lattice_stage(metric, s, out.search, make_seed, starts, progress);

  Pattern& p = out.best;
  p = pattern_of(out.search.best_problem);
  // Named after its settings, so that two designs can be told apart in a table.
  const std::string target =
      !s.api.empty() ? "-" + s.api : (s.lattice > 0 ? fmt::format("-lattice{}", s.lattice) : "");
  p.name = polish ? fmt::format("{}-optimized-{}{}", p.name, out.objective.tag(), target)
                  : fmt::format("{}-{}{}-seed{}", parse_family(s.family, out.placement).text(),
                                out.objective.tag(), target, s.seed);
  p.description = fmt::format("optimized {} for {}", family(p), metric.filter().name());
  p.provenance = {{"optimizer", out.method},
                  {"family", family(p)},
                  {"placement", out.placement},
                  {"filter", metric.filter().name()},
                  {"acuity", metric.acuity().name},
                  {"norm", format_norm(metric.norm())},
                  {"objective", out.objective.text()},
                  {"seed", std::to_string(s.seed)},
                  {"seeds", polish ? s.start_label : s.seeds},
                  {"start", std::to_string(best.start)},
                  {"iterations", std::to_string(best.run.iterations)},
                  {"weights", s.optimizer.weights_only ? "weights only" : "positions and weights"},
                  {"nonnegative", s.optimizer.nonnegative_weights ? "yes" : "no"},
                  {"pixel", s.strictly_inside ? "strictly inside" : "closed (border samples)"},
                  {"e2", fmt::format("{:.6f}", best.run.final_e2)}};
  if (out.lattice) {
    p.provenance.emplace_back("lattice", fmt::format("1/{} pixel", s.lattice));
    if (!out.lattice->profile.empty()) p.provenance.emplace_back("api", out.lattice->profile);
    p.provenance.emplace_back("lattice_e2", fmt::format("{:.6f}", metric.evaluate(p).e2));
  }
  validate(p);

  if (s.optimizer.nonnegative_weights && s.report_nonnegative_cost) {
    // What non-negative weights cost: the same best start, unconstrained.
    OptimizerSettings free = s.optimizer;
    free.nonnegative_weights = false;
    const Problem again = make_seed(best.start);
    const MultiStartResult r = multistart(
        metric, 1, s.seed, [&](int) { return again; }, free, s.threads);
    out.unconstrained_e2 = r.starts.empty() ? NAN : r.starts[0].run.final_e2;
  }
  return out;
}

OptimizeRunResult optimize_run(const Objective& objective, const OptimizeRunSettings& settings,
                               const StudyProgress& progress) {
  return optimize_run(objective.metric(), settings, progress);
}

JsonObject optimize_run_json(const OptimizeRunResult& r) {
  const StartRecord& best = r.best_start();
  JsonObject doc = json_report("optimize");
  doc.update(JsonObject{{"family", family(r.best)},
                        {"placement", r.placement},
                        {"method", method_key(r.settings.optimizer.method)}});
  doc.update(objective_json(r.objective));
  doc.update(JsonObject{{"seed", r.settings.seed},
                        {"starts", r.search.starts.size()},
                        {"best_start", best.start},
                        {"initial_e2", best.run.initial_e2},
                        {"e2", best.run.final_e2},
                        {"iterations", best.run.iterations}});
  if (r.lattice) {
    doc["lattice"] = r.lattice->steps;
    doc["lattice_e2"] = r.objective.metric().evaluate(r.best).e2;
  }
  doc["pattern"] = JsonObject::parse(pattern_to_json(r.best));
  return doc;
}

}  // namespace aapat
