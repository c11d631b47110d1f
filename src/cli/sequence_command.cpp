// `aapat sequence generate|eval|phases`: jitter and alternating-MSAA
// sequences, their temporal metrics under an accumulation model, and the
// phase count an upscaler uses for a ratio.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_json.h"
#include "aapat/temporal/temporal_metrics.h"
#include "cli/commands.h"
#include "cli/metric_options.h"

namespace aapat {
namespace {

struct ModelOptions {
  std::string model = "ema", resolve;
  double alpha = 0.1;
  int window = 0, radius = 1;

  void add_to(CLI::App* cmd) {
    cmd->add_option("--model", model, "accumulation: ema (history 1 - alpha) or box (a window)")
        ->capture_default_str()
        ->check(CLI::IsMember({"ema", "box"}));
    cmd->add_option("--alpha", alpha, "EMA blend factor, the current frame's weight, in (0, 1]")
        ->capture_default_str();
    cmd->add_option("--window", window, "box: frames averaged (0: the period)")
        ->capture_default_str();
    cmd->add_option("--resolve", resolve,
                    "resolve each frame over its neighbours' samples with this filter "
                    "(e.g. gaussian:sigma=0.47,radius=1.5)");
    cmd->add_option("--resolve-radius", radius, "pixels the resolve reads on each side (1: 3x3)")
        ->capture_default_str();
  }
  Accumulation make() const {
    Accumulation a;
    a.kind = model == "box" ? AccumulationKind::box : AccumulationKind::ema;
    a.alpha = alpha;
    a.window = window;
    a.resolve_radius = radius;
    if (!resolve.empty()) a.resolve = make_filter(resolve);
    try {
      validate(a);
    } catch (const ParameterError& e) {
      throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
    }
    return a;
  }
  std::string text() const {
    std::string t = model == "box" ? (window ? fmt::format("box of {} frames", window)
                                             : std::string("box of the period"))
                                   : fmt::format("EMA alpha {}", alpha);
    if (!resolve.empty())
      t += fmt::format(", {} resolve over {}x{}", resolve, 2 * radius + 1, 2 * radius + 1);
    return t;
  }
};

std::optional<Pattern> optional_pattern(const std::string& name) {
  if (name.empty()) return std::nullopt;
  return resolve_pattern(name);
}

void add_generate(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand("generate", "make a sequence from a generator spec");
  struct Options {
    std::string spec, pattern, output;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("spec", o->spec,
                  "halton:b1=2,b2=3,frames=8, r2:frames=16, sobol:frames=16,seed=1, "
                  "split:frames=K, rooks-order, blue-noise-order, "
                  "msaa-alternating:samples=2,frames=2 (see `aapat list`)")
      ->required();
  cmd->add_option("--pattern", o->pattern,
                  "the pattern split / rooks-order / blue-noise-order take apart");
  cmd->add_option("-o,--output", o->output, "write the sequence file (.json; - for stdout)")
      ->required();
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    if (o->output != "-" && !o->output.ends_with(".json"))
      throw Error(fmt::format("--output: '{}' must end in .json", o->output));
    const Sequence s = make_sequence(o->spec, optional_pattern(o->pattern));
    if (o->output == "-") {
      out << sequence_to_json(s);
      return;
    }
    save_sequence_file(s, o->output);
    out << fmt::format("wrote {}: {} frames of {}\n", o->output, s.period(), family(s.frames[0]));
  };
}

void add_eval(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "eval", "temporal metrics of sequences under an accumulation model, side by side");
  struct Options {
    std::vector<std::string> sequences;
    std::string pattern;
    MetricOptions metric;
    ModelOptions model;
    int curve = 0;
    bool json = false, prefixes = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences, "sequence files or generator specs")->required();
  cmd->add_option("--pattern", o->pattern, "for the generators that take a pattern apart");
  o->metric.add_to(cmd);
  o->model.add_to(cmd);
  cmd->add_option("--curve-frames", o->curve,
                  "frames of the convergence curve after a cut (0: until it settles)")
      ->capture_default_str();
  cmd->add_flag("--prefixes", o->prefixes,
                "also list every prefix's stratification and discrepancy");
  cmd->add_flag("--json", o->json, "print JSON (with the curves, flicker per phase and prefixes)");
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    const Metric metric = o->metric.make();
    const Accumulation model = o->model.make();
    const std::optional<Pattern> pattern = optional_pattern(o->pattern);
    std::vector<std::pair<Sequence, TemporalReport>> rows;
    for (const std::string& spec : o->sequences) {
      Sequence s = resolve_sequence(spec, pattern);
      TemporalReport r = evaluate_temporal(s, model, metric, o->curve);
      rows.emplace_back(std::move(s), std::move(r));
    }
    if (o->json) {
      JsonObject js = json_report("sequence eval");
      js.update(JsonObject{{"filter", metric.filter().name()},
                           {"acuity", metric.acuity().name},
                           {"norm", format_norm(metric.norm())},
                           {"model", o->model.text()}});
      JsonObject::array_t list;
      for (const auto& [s, r] : rows) {
        JsonObject::array_t prefixes;
        for (const PrefixMeasure& p : r.prefixes)
          prefixes.push_back(JsonObject{{"samples", p.samples},
                                        {"most_in_x", p.most_in_x},
                                        {"most_in_y", p.most_in_y},
                                        {"star", p.star},
                                        {"l2_star", p.l2_star}});
        list.push_back(
            JsonObject{{"sequence", s.name},
                       {"frames", s.period()},
                       {"family", family(s.frames[0])},
                       {"worst_e2", r.worst_e2},
                       {"mean_e2", r.mean_e2},
                       {"steady_e2", r.steady_e2},
                       {"cut_curve", r.cut_curve},
                       {"settle_frame", r.settle_frame},
                       {"worst_flicker", r.worst_flicker},
                       {"mean_flicker", r.mean_flicker},
                       {"flicker", r.flicker},
                       {"mean_offset", JsonObject::array({r.mean_offset.x, r.mean_offset.y})},
                       {"worst_centroid", r.worst_centroid},
                       {"prefixes", prefixes}});
      }
      js["rows"] = list;
      out << json_text(js);
      return;
    }
    out << fmt::format("{}; filter {}, acuity {}, norm {}\n", o->model.text(),
                       metric.filter().name(), metric.acuity().name, format_norm(metric.norm()));
    size_t width = 8;
    for (const auto& row : rows) width = std::max(width, row.first.name.size());
    out << fmt::format("{:<{}} {:>6} {:>9} {:>9} {:>9} {:>9} {:>7} {:>9} {:>9} {:>9}\n", "sequence",
                       width, "frames", "worst E2", "mean E2", "flicker", "mean flk", "settle",
                       "offset", "centroid", "star D*");
    for (const auto& [s, r] : rows)
      out << fmt::format(
          "{:<{}} {:>6} {:>9.4f} {:>9.4f} {:>9.4f} {:>9.4f} {:>7} {:>9.5f} {:>9.5f} "
          "{:>9.5f}\n",
          s.name, width, s.period(), r.worst_e2, r.mean_e2, r.worst_flicker, r.mean_flicker,
          r.settle_frame, std::hypot(r.mean_offset.x, r.mean_offset.y), r.worst_centroid,
          r.prefixes.back().star);
    if (!o->prefixes) return;
    for (const auto& [s, r] : rows) {
      out << fmt::format(
          "\n{}: prefixes (most samples in one of m strata of x, of y; 1 is "
          "N-rooks)\n{:>6} {:>6} {:>6} {:>10} {:>10}\n",
          s.name, "m", "x", "y", "star D*", "L2-star");
      for (const PrefixMeasure& p : r.prefixes)
        out << fmt::format("{:>6} {:>6} {:>6} {:>10.6f} {:>10.6f}\n", p.samples, p.most_in_x,
                           p.most_in_y, p.star, p.l2_star);
    }
  };
}

void add_phases(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "phases", "the jitter phase count FSR 2 uses for an upscale (its source's formula)");
  struct Options {
    double ratio = 0;
    int render = 0, display = 0;
  };
  auto o = std::make_shared<Options>();
  auto* ratio = cmd->add_option("--ratio", o->ratio, "display width / render width, e.g. 1.5");
  auto* render = cmd->add_option("--render", o->render, "render width in pixels");
  auto* display = cmd->add_option("--display", o->display, "display width in pixels");
  ratio->excludes(render)->excludes(display);
  render->needs(display);
  display->needs(render);
  action = [o, cmd, ratio](std::ostream& out) {
    if (!cmd->parsed()) return;
    if (ratio->count() == 0 && o->render == 0)
      throw Error("give --ratio R or --render W --display W");
    try {
      const int phases = ratio->count() ? upscaler_phase_count(o->ratio)
                                        : upscaler_phase_count(o->render, o->display);
      out << phases << "\n";
    } catch (const ParameterError& e) {
      throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
    }
  };
}

}  // namespace

Action add_sequence_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "sequence",
      "patterns over time: TAA and upscaler jitter, alternating MSAA (docs/temporal.md)");
  cmd->require_subcommand(1);
  auto actions = std::make_shared<std::vector<std::function<void(std::ostream&)>>>(3);
  add_generate(cmd, (*actions)[0]);
  add_eval(cmd, (*actions)[1]);
  add_phases(cmd, (*actions)[2]);
  return [actions](std::ostream& out) {
    for (auto& a : *actions) a(out);
  };
}

}  // namespace aapat
