// `aapat sequence generate|eval|phases`: jitter and alternating-MSAA
// sequences, their temporal metrics under an accumulation model, and the
// phase count an upscaler uses for a ratio.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>

#include "aapat/core/hardware_layout.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/point_set_file.h"
#include "aapat/temporal/engine/engine_pans.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/model_json.h"
#include "aapat/temporal/model/pan_distribution.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/model/temporal_metrics.h"
#include "aapat/temporal/sequence/sequence_export.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "aapat/temporal/sequence/sequence_svg.h"
#include "cli/app.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"
#include "cli/sequence_options.h"

namespace aapat {
namespace {

constexpr size_t kMaxPanColumns = 8;  // velocities shown one by one in the text table

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
    double ratio = 1;
    bool json = false, prefixes = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences, "sequence files or generator specs")->required();
  cmd->add_option("--ratio", o->ratio,
                  "display / render resolution (>= 1): each frame reconstructed into display "
                  "pixels, as optimize --sequence --ratio and sequence pan --ratio model it")
      ->capture_default_str();
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
    const Objective objective = o->metric.resolve();
    const Metric metric = objective.metric();
    const Accumulation model = o->model.make();
    const std::optional<Pattern> pattern = optional_pattern(o->pattern);
    std::vector<std::pair<Sequence, TemporalReport>> rows;
    for (const std::string& spec : o->sequences) {
      Sequence s = resolve_sequence(spec, pattern);
      TemporalReport r =
          evaluate_temporal(s, model, metric, o->curve,
                            o->ratio != 1 ? std::optional(make_upscale(o->ratio)) : std::nullopt);
      rows.emplace_back(std::move(s), std::move(r));
    }
    if (o->json) {
      JsonObject js = json_report("sequence eval");
      js.update(objective_json(objective));
      js["model"] = o->model.text();
      js["ratio"] = o->ratio;
      JsonObject::array_t list;
      for (const auto& [s, r] : rows) list.push_back(temporal_report_json(s, r));
      js["rows"] = list;
      out << json_text(js);
      return;
    }
    out << fmt::format("{}{}; {}\n", o->model.text(),
                       o->ratio != 1 ? fmt::format(", render scale 1/{}", o->ratio) : "",
                       objective.caption());
    size_t width = 8;
    for (const auto& row : rows) width = std::max(width, row.first.name.size());
    out << fmt::format("{:<{}} {:>6} {:>9} {:>9} {:>9} {:>9} {:>7} {:>9} {:>9} {:>9}\n", "sequence",
                       width, "frames", "worst E2", "mean E2", "flicker", "worst flk", "settle",
                       "offset", "centroid", "star D*");
    for (const auto& [s, r] : rows)
      out << fmt::format(
          "{:<{}} {:>6} {:>9.4f} {:>9.4f} {:>9.4f} {:>9.4f} {:>7} {:>9.5f} {:>9.5f} "
          "{:>9.5f}\n",
          s.name, width, s.period(), r.worst_e2, r.mean_e2, r.mean_flicker, r.worst_flicker,
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

void add_pan(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "pan",
      "steady E2 and flicker of jitters under an engine preset's history while the scene pans "
      "(the linear model before rectification, docs/temporal.md)");
  struct Options {
    std::vector<std::string> sequences, velocities{kPanVelocities.begin(), kPanVelocities.end()};
    std::string taa;
    std::vector<std::string> taa_set;
    double ratio = 1, max_speed = kDefaultRandomPanSpeed;
    int random_velocities = 0;
    uint64_t seed = 1;
    MetricOptions metric;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences,
                  "sequence files or generator specs (a generator without frames= takes the "
                  "upscaler's phases for --ratio); each after the first is compared with it")
      ->required();
  cmd->add_option("--taa", o->taa,
                  "the engine preset: its reconstruction, history sampler and blend")
      ->required();
  cmd->add_option("--taa-set", o->taa_set,
                  "KEY=VALUE: override one of the preset's settings, as `animate --taa-set` does "
                  "(the model takes reconstruct, history and the blend's; rectification is not "
                  "in it)");
  auto* ratio = cmd->add_option("--ratio", o->ratio, "display / render resolution (>= 1)")
                    ->capture_default_str();
  auto* velocity =
      cmd->add_option(
             "--velocity", o->velocities,
             "DX,DY display pixels per frame, repeatable (0,0: still, the preset's still blend)")
          ->capture_default_str();
  cmd->add_option("--random-velocities", o->random_velocities,
                  fmt::format("N more velocities, each component uniform in +-MAX_SPEED from "
                              "--seed (1 to {}; without --velocity, instead of its defaults): "
                              "a comparison over many pans, as the velocity decides each one",
                              kMaxRandomPanVelocities));
  cmd->add_option("--max-speed", o->max_speed,
                  "--random-velocities: the largest component, display pixels per frame")
      ->capture_default_str();
  cmd->add_option("--seed", o->seed, "--random-velocities: the random seed")->capture_default_str();
  o->metric.add_to(cmd);
  cmd->add_flag("--json", o->json, "print JSON");
  action = [o, cmd, ratio, velocity](std::ostream& out) {
    if (!cmd->parsed()) return;
    const Objective objective = o->metric.resolve();
    const Metric metric = objective.metric();
    const EngineTaa taa = make_engine_taa(o->taa, o->ratio, parse_taa_overrides(o->taa_set));
    std::optional<std::vector<Vec2>> given;
    if (velocity->count()) {
      given.emplace();
      for (const std::string& v : o->velocities) given->push_back(parse_velocity(v));
    }
    const std::vector<Vec2> velocities =
        pan_velocities(given, o->random_velocities, o->max_speed, o->seed);
    std::vector<Sequence> sequences;
    for (const std::string& spec : o->sequences) {
      std::string warning;
      sequences.push_back(
          resolve_sequence_for_ratio(spec, o->ratio, ratio->count() ? &warning : nullptr));
      if (!warning.empty()) warnings() << "aapat: warning: " << warning << "\n";
    }
    PanTable table;
    {
      Progress bar("pan");
      table = evaluate_pans(sequences, taa, velocities, metric, bar.callback());
    }
    if (o->json) {
      JsonObject js = json_report("sequence pan");
      js.update(objective_json(objective));
      js["taa"] = o->taa;
      js["taa_settings"] = engine_taa_text(taa);
      js["ratio"] = o->ratio;
      js["rows"] = pan_rows_json(table);
      out << json_text(js);
      return;
    }
    out << fmt::format("{}, panning: steady mean E2 / mean flicker per velocity (px/frame); {}\n",
                       engine_taa_text(taa), objective.caption());
    // Past kMaxPanColumns velocities (--json has each) only the mean.
    const bool each = velocities.size() <= kMaxPanColumns;
    size_t width = 8;
    for (const Sequence& s : sequences) width = std::max(width, s.name.size());
    out << fmt::format("{:<{}}", "sequence", width);
    if (each)
      for (const Vec2 v : velocities)
        out << fmt::format(" {:>15}", fmt::format("{:g},{:g}", v.x, v.y));
    out << fmt::format(" {:>15}\n", each ? "mean" : fmt::format("mean of {}", velocities.size()));
    for (const PanRow& row : table.rows) {
      out << fmt::format("{:<{}}", row.sequence, width);
      if (each)
        for (const PanReport& r : row.at)
          out << fmt::format(" {:>7.4f}/{:<7.4f}", r.mean_e2, r.flicker);
      out << fmt::format(" {:>7.4f}/{:<7.4f}\n", row.mean.mean_e2, row.mean.flicker);
    }
    for (const PanRow& row : table.rows) {
      if (!row.against_first) continue;
      const PanComparison& c = *row.against_first;
      out << fmt::format(
          "{} against {}: mean E2 lower at {} of {} velocities, {:+.2f} % on "
          "average ({:+.1f} % to {:+.1f} %)\n",
          row.sequence, table.rows[0].sequence, c.lower, c.velocities, 100 * c.mean_change,
          100 * c.lowest_change, 100 * c.highest_change);
    }
  };
}

void add_show(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "show", "draw every frame's samples numbered in time order, and the convergence curve");
  struct Options {
    std::vector<std::string> sequences;
    std::string pattern, output, curve;
    MetricOptions metric;
    ModelOptions model;
    int frames = 0;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences,
                  "sequence files or generator specs (the drawing: the first)")
      ->required();
  cmd->add_option("--pattern", o->pattern, "for the generators that take a pattern apart");
  cmd->add_option("-o,--output", o->output, "the frames' samples (.svg)");
  cmd->add_option("--curve", o->curve, "E2 after a cut, frame by frame, every sequence (.svg)");
  cmd->add_option("--curve-frames", o->frames, "frames of the curve (0: until it settles)")
      ->capture_default_str();
  o->metric.add_to(cmd);
  o->model.add_to(cmd);
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    if (o->output.empty() && o->curve.empty())
      throw Error("show: give -o FILE.svg and/or --curve FILE.svg");
    for (const std::string* path : {&o->output, &o->curve})
      if (!path->empty() && *path != "-" && !path->ends_with(".svg"))
        throw Error(fmt::format("'{}' must end in .svg", *path));
    const std::optional<Pattern> pattern = optional_pattern(o->pattern);
    std::vector<Sequence> list;
    for (const std::string& spec : o->sequences) list.push_back(resolve_sequence(spec, pattern));
    if (!o->output.empty()) write_output(o->output, sequence_svg(list.front()), out);
    if (!o->curve.empty()) {
      const Objective objective = o->metric.resolve();
      const Metric metric = objective.metric();
      const Accumulation model = o->model.make();
      std::vector<CurveSeries> series;
      int frames = o->frames;
      if (frames == 0)  // one length for all: the longest automatic curve
        for (const Sequence& s : list)
          frames = std::max(frames,
                            static_cast<int>(evaluate_temporal(s, model, metric).cut_curve.size()));
      for (const Sequence& s : list)
        series.push_back({s.name, evaluate_temporal(s, model, metric, frames).cut_curve});
      write_output(o->curve,
                   convergence_svg(series, fmt::format("E2 after a cut, {}, objective {}",
                                                       o->model.text(), objective.text())),
                   out);
    }
    for (const std::string* path : {&o->output, &o->curve})
      if (!path->empty() && *path != "-") out << "wrote " << *path << "\n";
  };
}

void add_export(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "export",
      "a jitter as a constant array (HLSL, GLSL, C++), or alternating MSAA frames for an "
      "API profile");
  struct Options {
    std::string sequence, pattern, language = "hlsl", y = "down", api, output = "-";
    bool points = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequence", o->sequence, "sequence file or generator spec")->required();
  cmd->add_option("--pattern", o->pattern, "for the generators that take a pattern apart");
  cmd->add_option("--language", o->language, "jitter arrays: hlsl, glsl or c++")
      ->capture_default_str()
      ->check(CLI::IsMember({"hlsl", "glsl", "c++", "cpp"}));
  cmd->add_option("--y", o->y, "jitter arrays: +y down (screen rows) or up (aapat's convention)")
      ->capture_default_str()
      ->check(CLI::IsMember({"down", "up"}));
  cmd->add_option("--api", o->api,
                  "several samples per frame: the profile (d3d12-tier1, d3d12-tier2, vulkan, "
                  "metal, gl, or all); each frame snapped to its 1/16 lattice");
  cmd->add_flag("--points", o->points,
                "the samples of pixel 0 in time order, in [0, 1)^2, as a point CSV: its first m "
                "rows are the prefix of m samples, for aapat spectrum and discrepancy");
  cmd->add_option("-o,--output", o->output, "file to write (- for stdout)")->capture_default_str();
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    const Sequence s = resolve_sequence(o->sequence, optional_pattern(o->pattern));
    std::string text;
    if (o->points) {
      if (!o->api.empty()) throw Error("--points writes the samples alone: give no --api");
      text = point_csv(sequence_points(s));
    } else if (o->api.empty()) {
      text = export_jitter(s, parse_export_language(o->language), o->y == "down");
    } else if (o->api == "all") {  // every profile that holds the frames
      for (const ApiProfile& profile : api_profiles()) {
        try {
          text += export_msaa_sequence(s, profile) + "\n";
        } catch (const Error& e) {
          text += fmt::format("// {}: not exported: {}\n\n", profile.name, e.what());
        }
      }
    } else {
      text = export_msaa_sequence(s, api_profile(o->api));
    }
    write_output(o->output, text, out);
    if (o->output != "-") out << "wrote " << o->output << "\n";
  };
}

}  // namespace

Action add_sequence_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("sequence",
                                 "patterns over time: TAA and upscaler jitter, alternating MSAA: "
                                 "generate, eval, show, export, phases, pan, compare, search "
                                 "(docs/temporal.md)");
  cmd->require_subcommand(1);
  auto actions = std::make_shared<std::vector<std::function<void(std::ostream&)>>>(8);
  add_generate(cmd, (*actions)[0]);
  add_eval(cmd, (*actions)[1]);
  add_show(cmd, (*actions)[2]);
  add_export(cmd, (*actions)[3]);
  add_phases(cmd, (*actions)[4]);
  add_pan(cmd, (*actions)[5]);
  add_sequence_compare(cmd, (*actions)[6]);
  add_sequence_search(cmd, (*actions)[7]);
  return [actions](std::ostream& out) {
    for (auto& a : *actions) a(out);
  };
}

}  // namespace aapat
