// `aapat optimize`: multi-start optimization of a family (Laine-Aila Sec. 5),
// or polishing of an existing pattern.
#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <ostream>

#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"
#include "core/hardware_layout.h"
#include "core/lattice.h"
#include "generate/enumerate.h"
#include "io/json_report.h"
#include "io/pattern_json.h"
#include "io/pattern_svg.h"
#include "optimize/family.h"
#include "optimize/lattice_search.h"
#include "optimize/multistart.h"

namespace aapat {

Action add_optimize_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "optimize", "optimize positions and weights: a family from random starts, or a pattern");
  struct Options {
    std::string pattern, family, placement, seeds = "jittered", method = "descent";
    std::string output, csv, svg, api;
    MetricOptions metric;
    int lattice = 0;
    int starts = 16, threads = 0, iterations = 4000;
    uint64_t seed = 1;
    double time_limit = 0;
    std::vector<int> lock;
    bool weights_only = false, nonnegative = false, starts_given = false, json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("pattern", o->pattern, "catalog name or pattern file to polish");
  cmd->add_option("--family", o->family, "family to search, e.g. 'P(4,1+,2)'");
  cmd->add_option("--placement", o->placement,
                  "sites of the base pixel's samples: inside, left, right, bottom, top, "
                  "bottom-left, ... (FLIPQUAD: left,right,bottom,top)");
  o->metric.add_to(cmd);
  cmd->add_option("--starts", o->starts, "random starts (run in parallel)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--seeds", o->seeds,
                  "seed patterns: jittered, poisson, uniform, or a pattern file (.json) whose "
                  "starts after the first are jittered by up to 0.1 pixel")
      ->capture_default_str();
  cmd->add_option("--lock", o->lock, "samples of the base pixel (set 0) to keep fixed, e.g. 0,2")
      ->delimiter(',');
  cmd->add_option("--time-limit", o->time_limit, "seconds for the whole run (0: none)")
      ->check(CLI::Range(0.0, 1e7));
  cmd->add_option("--iterations", o->iterations, "iterations per start at most")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000000));
  cmd->add_option("--method", o->method,
                  "descent (Laine-Aila heuristic), minimax (eps-active min-norm descent) or anneal")
      ->capture_default_str()
      ->check(CLI::IsMember({"descent", "minimax", "anneal"}));
  cmd->add_option("--threads", o->threads, "threads (0: all cores)")->check(CLI::Range(0, 1024));
  cmd->add_option("--lattice", o->lattice,
                  "then search positions on the 1/N-pixel lattice (16: programmable MSAA)")
      ->check(CLI::Range(2, 256));
  cmd->add_option("--api", o->api,
                  "with --lattice: the pattern must fit this API profile (d3d12-tier1, "
                  "d3d12-tier2, vulkan, metal, gl)");
  cmd->add_flag("--weights-only", o->weights_only, "keep positions, optimize weights (Opt W)");
  cmd->add_flag("--nonnegative", o->nonnegative, "keep weights >= 0 and report the E2 this costs");
  cmd->add_option("-o,--output", o->output, "write the best pattern (.json)");
  cmd->add_option("--csv", o->csv,
                  "write every start: start, initial E2, final E2, iterations, seconds");
  cmd->add_option("--svg", o->svg, "write a drawing of the best pattern");
  cmd->add_flag("--json", o->json, "print the result as JSON (docs/json.md)");

  auto* starts_option = cmd->get_option("--starts");
  return [o, starts_option](std::ostream& out) {
    o->starts_given = starts_option->count() > 0;
    if (o->pattern.empty() == o->family.empty())
      throw Error("optimize: give either --family (a search) or a PATTERN to polish");
    if (!o->output.empty() && !o->output.ends_with(".json"))
      throw Error(fmt::format("--output: '{}' must end in .json", o->output));
    const Metric metric = o->metric.make();
    if (!o->api.empty() && o->lattice == 0) o->lattice = kLatticeSteps;
    const ApiProfile* profile = o->api.empty() ? nullptr : &api_profile(o->api);
    if (profile && o->lattice != kLatticeSteps)
      throw Error(fmt::format("--api {}: the APIs' lattice is 1/16 pixel, not --lattice {}", o->api,
                              o->lattice));
    OptimizerSettings settings;
    settings.method = o->method == "anneal"    ? Method::kAnneal
                      : o->method == "minimax" ? Method::kMinimax
                                               : Method::kDescent;
    settings.max_iterations = o->iterations;
    settings.weights_only = o->weights_only;
    settings.nonnegative_weights = o->nonnegative;
    if (o->time_limit > 0)
      settings.deadline = std::chrono::steady_clock::now() +
                          std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(o->time_limit));

    SeedFunction make_seed;
    std::string what;
    int starts = o->starts;
    FamilySpec spec;
    if (!o->family.empty() && o->seeds.ends_with(".json")) {
      // Seeds from a file: the same as polishing it, in the family asked for.
      const Pattern file = load_pattern_file(o->seeds);
      if (family(file) != parse_family(o->family, o->placement).text())
        throw Error(fmt::format("--seeds: {} is {}, not the --family {}", o->seeds, family(file),
                                o->family));
      o->pattern = o->seeds;
    }
    if (!o->pattern.empty()) {
      // Start 0 is the pattern itself; later starts jitter it.
      Problem start = problem_from_pattern(resolve_pattern(o->pattern));
      lock_samples(start, o->lock);
      const uint64_t seed = o->seed;
      make_seed = [start, seed](int i) {
        if (i == 0) return start;
        auto rng = start_rng(seed, static_cast<uint64_t>(i));
        return perturbed(start, 0.1, rng);
      };
      starts = o->starts_given ? o->starts : 1;
      what = fmt::format("{} {} ({} start{})", start.layout.name, family(start.layout), starts,
                         starts == 1 ? "" : "s");
    }
    // A sharing family without a placement: every placement of its cost is
    // searched (as `aapat enumerate` does) and the best one kept; otherwise
    // every sample would sit inside and nothing would be shared.
    std::vector<std::string> placements{o->placement};
    if (o->pattern.empty()) {
      spec = parse_family(o->family, o->placement);
      if (spec.mirrored && o->placement.empty()) {
        placements.clear();
        for (const PlacementConfig& c : enumerate_placements(spec.n))
          placements.push_back(c.sites());
      }
    }
    auto seeds_for = [&](const std::string& placement) -> SeedFunction {
      const FamilySpec s = parse_family(o->family, placement);
      SeedFunction random = family_seeds(s, parse_seed_kind(o->seeds), o->seed, metric.filter());
      const std::vector<int> lock = o->lock;
      return [random, lock](int i) {
        Problem p = random(i);
        lock_samples(p, lock);
        return p;
      };
    };

    const auto t0 = std::chrono::steady_clock::now();
    MultiStartResult result;
    {
      Progress bar("optimize");
      const int total = starts * static_cast<int>(o->pattern.empty() ? placements.size() : 1);
      int before = 0;
      auto progress = [&](int done, int, double best) {
        bar.update(before + done, total, fmt::format("best E2 {:.4f}", best));
      };
      if (!o->pattern.empty()) {
        result = multistart(metric, starts, o->seed, make_seed, settings, o->threads, progress);
      } else {
        for (const std::string& placement : placements) {
          SeedFunction seeds = seeds_for(placement);
          MultiStartResult r =
              multistart(metric, starts, o->seed, seeds, settings, o->threads, progress);
          before += starts;
          if (r.best >= 0 && (result.best < 0 || r.starts[r.best].run.final_e2 <
                                                     result.starts[result.best].run.final_e2)) {
            result = std::move(r);
            make_seed = std::move(seeds);
            o->placement = placement;
          }
        }
        spec = parse_family(o->family, o->placement);
        what = placements.size() > 1
                   ? fmt::format("{} from {} {} starts for each of its {} placements (best: {})",
                                 spec.text(), starts, o->seeds, placements.size(), o->placement)
                   : fmt::format("{} from {} {} starts", spec.text(), starts, o->seeds);
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (result.best < 0) throw Error("optimize: the time limit passed before any start ran");
    const StartRecord& best = result.starts[result.best];

    // On the lattice: from the continuous optimum, kicks around it, and fresh seeds, all snapped.
    std::string lattice_report;
    if (o->lattice > 0) {
      if (profile)  // fails early, naming the reason, if the family cannot fit the profile
        hardware_layout(snap_to_lattice(pattern_of(make_seed(0)), o->lattice), *profile);
      const LatticeSearch lat = lattice_search_from(metric, result.best_problem, make_seed, starts,
                                                    o->seed, o->lattice, settings);
      result.best_problem = lat.best;
      lattice_report = fmt::format(
          "lattice 1/{}{}: continuous E2 {:.4f}, snapped {:.4f}, lattice optimum {:.4f} ({:+.4f}; "
          "best of {} lattice starts, start {}, {} moves)\n",
          o->lattice, profile ? fmt::format(" for {}", profile->name) : "", best.run.final_e2,
          lat.run.snapped_e2, lat.run.final_e2, lat.run.final_e2 - best.run.final_e2, lat.starts,
          lat.best_start, lat.run.moves);
      if (profile) {
        const HardwareLayout L = hardware_layout(pattern_of(lat.best), *profile);
        lattice_report += fmt::format(
            "{}: {}x{} pixel grid, {}x MSAA, {} samples per pixel, the resolve reads {} per "
            "output pixel\n",
            profile->name, L.grid_w, L.grid_h, L.sample_count,
            format_cost(samples_per_pixel(pattern_of(lat.best))), format_cost(L.reads()));
      }
    }

    Pattern p = pattern_of(result.best_problem);
    if (!o->pattern.empty()) {
      p.name = p.name + "-optimized";
    } else {
      p.name = fmt::format("best-{}", spec.text());
    }
    p.description = fmt::format("optimized {} for {}", family(p), metric.filter().name());
    p.provenance = {
        {"optimizer", o->method == "anneal"    ? "simulated annealing"
                      : o->method == "minimax" ? "eps-active minimum-norm descent"
                                               : "Laine-Aila heuristic (t 0.99, c1 = 100 c0)"},
        {"family", family(p)},
        {"placement", o->placement},
        {"filter", metric.filter().name()},
        {"acuity", metric.acuity().name},
        {"norm", o->metric.norm},
        {"seed", std::to_string(o->seed)},
        {"seeds", o->pattern.empty() ? o->seeds : o->pattern},
        {"start", std::to_string(best.start)},
        {"iterations", std::to_string(best.run.iterations)},
        {"weights", o->weights_only ? "weights only" : "positions and weights"},
        {"nonnegative", o->nonnegative ? "yes" : "no"},
        {"e2", fmt::format("{:.6f}", best.run.final_e2)}};
    if (o->lattice > 0) {
      p.provenance.emplace_back("lattice", fmt::format("1/{} pixel", o->lattice));
      if (profile) p.provenance.emplace_back("api", profile->name);
      p.provenance.emplace_back("lattice_e2", fmt::format("{:.6f}", metric.evaluate(p).e2));
    }
    validate(p);

    // With --json the document alone goes to stdout.
    std::ostream discard(nullptr);
    std::ostream& text = o->json ? discard : out;

    text << fmt::format("optimized {} ({}, acuity {}, norm {})\n", what, metric.filter().name(),
                        metric.acuity().name, o->metric.norm);
    text << fmt::format(
        "{} starts ran in {:.2f} s; best start {}: E2 {:.4f} -> {:.4f} in {} iterations\n",
        result.starts.size(), seconds, best.start, best.run.initial_e2, best.run.final_e2,
        best.run.iterations);
    if (result.polished_from > 0)
      text << fmt::format(
          "(the heuristic's best {:.5f}, polished by the minimax descent to {:.5f})\n",
          result.polished_from, best.run.final_e2);
    if (o->nonnegative) {
      // What non-negative weights cost: the same best start, unconstrained.
      OptimizerSettings free = settings;
      free.nonnegative_weights = false;
      Problem again = make_seed(best.start);
      const MultiStartResult unconstrained = multistart(
          metric, 1, o->seed, [&](int) { return again; }, free, o->threads);
      const double e_free =
          unconstrained.starts.empty() ? NAN : unconstrained.starts[0].run.final_e2;
      text << fmt::format(
          "non-negative weights: E2 {:.4f}; unconstrained from the same start: {:.4f} "
          "(cost {:+.4f})\n",
          best.run.final_e2, e_free, best.run.final_e2 - e_free);
    }
    text << lattice_report;
    text << fmt::format("{}  {}  n = {}\n", p.name, family(p), format_cost(samples_per_pixel(p)));
    for (const Vec2& s : p.sets[0])
      text << fmt::format("  {:>9.5f} {:>9.5f}  {}\n", s.x, s.y, site_name(s));
    text << "  weights:";
    for (double w : p.weights[0]) text << fmt::format(" {:.5f}", w);
    text << "\n";

    if (!o->output.empty()) {
      save_pattern_file(p, o->output);
      text << "wrote " << o->output << "\n";
    }
    if (!o->svg.empty()) {
      write_output(o->svg, pattern_svg(p), out);
      text << "wrote " << o->svg << "\n";
    }
    if (!o->csv.empty()) {
      std::string csv = "start,initial_e2,final_e2,iterations,seconds\n";
      for (const auto& r : result.starts)
        csv += fmt::format("{},{:.10g},{:.10g},{},{:.4f}\n", r.start, r.run.initial_e2,
                           r.run.final_e2, r.run.iterations, r.seconds);
      write_output(o->csv, csv, out);
      text << "wrote " << o->csv << "\n";
    }
    if (o->json) {
      JsonObject doc = json_report("optimize");
      doc.update(JsonObject{{"family", family(p)},
                            {"placement", o->placement},
                            {"method", o->method},
                            {"filter", metric.filter().name()},
                            {"acuity", metric.acuity().name},
                            {"norm", o->metric.norm},
                            {"seed", o->seed},
                            {"starts", result.starts.size()},
                            {"best_start", best.start},
                            {"initial_e2", best.run.initial_e2},
                            {"e2", best.run.final_e2},
                            {"iterations", best.run.iterations}});
      if (o->lattice > 0) {
        doc["lattice"] = o->lattice;
        doc["lattice_e2"] = metric.evaluate(p).e2;
      }
      doc["pattern"] = JsonObject::parse(pattern_to_json(p));
      out << json_text(doc);
    }
  };
}

}  // namespace aapat
