// `aapat render SCENE`: an analytic scene (or a scene file) sampled with a
// pattern or a per-pixel generator, reconstructed with the pattern's weights
// or a filter; optionally against a dense reference, with the error figures.
// With --grid, rows of samplings x columns of filters in one contact sheet.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/contact_sheet.h"
#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/png_image.h"
#include "aapat/io/refinement_map.h"
#include "aapat/io/scene_json.h"
#include "aapat/study/study_json.h"
#include "aapat/temporal/engine/taa_render.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "cli/commands.h"
#include "cli/option_modes.h"
#include "cli/progress.h"
#include "cli/reference_options.h"
#include "cli/sequence_options.h"

namespace aapat {
namespace {

struct Options {
  // The defaults are the library's (default-constructed settings).
  std::string scene, pattern, generator, filter,
      size = fmt::format("{}x{}", RenderSettings{}.width, RenderSettings{}.height), output;
  std::string error_png, histogram, histogram_svg, translate, table, reference_png;
  std::string texture, refinement_map;
  // Set on `rendering` through RenderOptions::set, which checks each value.
  std::string mode, shading_point, texture_filter, lod, mipmap, adaptive;
  std::optional<double> threshold;
  std::optional<int> max_depth, max_samples, per_square;
  ReferenceOptions reference;
  double rotate = 0, scale = 1;
  int samples = Sampling{}.samples, zoom = 1;
  uint64_t seed = Sampling{}.seed;
  bool json = false, grid = false, measure = false;
  // Temporal mode: a sequence accumulated over frames of the static scene.
  std::string sequence;
  ModelOptions model;
  int frames = 0;
  bool cut = false;
  std::vector<std::string> rows = RenderGridSettings{}.rows, columns = RenderGridSettings{}.columns;
};

// The reference every figure of this run is measured against.
ReferenceSettings reference_settings(const Options& o) {
  ReferenceSettings ref = o.reference.settings;
  ref.seed = reference_seed(o.seed);
  return ref;
}

Scene make_view_scene(const Options& o, int w, int h) {
  Vec2 translation{0, 0};
  if (!o.translate.empty()) {
    const auto parts = split(o.translate);
    if (parts.size() != 2) throw Error(fmt::format("--translate: '{}' is not X,Y", o.translate));
    translation = {parse_number(parts[0], "--translate"), parse_number(parts[1], "--translate")};
  }
  Scene scene =
      view_scene(resolve_scene(o.scene, w, h, o.texture), w, h, o.rotate, o.scale, translation);
  for (const std::string& warning : scene_warnings(scene))
    std::cerr << "aapat: warning: " << warning << "\n";
  return scene;
}

// The shading and refinement options given on the command line.
RenderOptions render_options(const Options& o) {
  RenderOptions r;
  const std::pair<const char*, const std::string*> texts[] = {{"mode", &o.mode},
                                                              {"shading-point", &o.shading_point},
                                                              {"texture-filter", &o.texture_filter},
                                                              {"lod", &o.lod},
                                                              {"mipmap", &o.mipmap},
                                                              {"adaptive", &o.adaptive}};
  for (const auto& [key, value] : texts)
    if (!value->empty()) r.set(key, *value, "--" + std::string(key));
  if (o.threshold) r.threshold = *o.threshold;
  if (o.max_depth) r.max_depth = *o.max_depth;
  if (o.max_samples) r.max_samples = *o.max_samples;
  if (o.per_square) r.per_square = *o.per_square;
  const bool refinement =
      o.threshold || o.max_depth || o.max_samples || o.per_square || !o.refinement_map.empty();
  if (refinement && r.adaptive.empty())
    throw Error(
        "--threshold, --max-depth, --max-samples, --per-square and --refinement-map "
        "are for --adaptive CRITERION");
  return r;
}

std::string ssim_text(const RenderFigures& f) {
  return f.ssim ? fmt::format("{:.4f}", *f.ssim) : "-";
}

void run_grid(const Options& o, std::ostream& out) {
  const auto [w, h] = parse_size(o.size, "--size", kMaxImageSide);
  if (o.output.empty() || !o.output.ends_with(".png"))
    throw Error("render --grid: give the sheet's file with -o SHEET.png");
  const Scene scene = make_view_scene(o, w, h);
  const RenderGridSettings s{w, h, o.rows, o.columns, o.seed, reference_settings(o)};
  std::vector<RenderGridCell> cells;
  {
    Progress bar("render");
    cells = render_grid(scene, s, o.reference.source(), bar.callback());
  }
  // A row's or column's label= names it on the sheet; else its text does.
  auto labels = [](const std::vector<std::string>& texts) {
    std::vector<std::string> out;
    for (const std::string& t : texts) {
      RenderOptions options;
      split_options(t, options);
      out.push_back(options.label.empty() ? t : options.label);
    }
    return out;
  };
  ContactSheet sheet{
      fmt::format("{}{} {}x{}", o.scene, o.texture.empty() ? "" : " texture " + o.texture, w, h),
      labels(o.rows),
      labels(o.columns),
      {},
      o.zoom};
  // Texture lookups and refinement get columns of their own when a cell has them.
  bool lookups = false, refined = false;
  for (const RenderGridCell& c : cells) {
    lookups = lookups || c.stats.lookups_per_pixel > 0;
    refined = refined || c.adaptive.has_value();
  }
  std::string table = "| sampling | filter | samples/pixel |";
  std::string rule = "| --- | --- | ---: |";
  if (lookups) table += " lookups/pixel |", rule += " ---: |";
  if (refined) table += " refined |", rule += " ---: |";
  table += " RMSE | max dev. | SSIM | FLIP |\n" + rule + " ---: | ---: | ---: | ---: |\n";
  // Refinement maps on one scale: 1 sample to the most any mapped cell took
  // (a uniform sampling's map is its constant count).
  const size_t pixels = static_cast<size_t>(w) * h;  // (clang 14 captures no structured binding)
  auto map_of = [&](const RenderGridCell& c) {
    return c.adaptive
               ? c.adaptive->samples
               : std::vector<int>(pixels, static_cast<int>(std::lround(c.stats.samples_per_pixel)));
  };
  int most = 1;
  for (const RenderGridCell& c : cells)
    if (c.show_map) {
      const std::vector<int> map = map_of(c);
      most = std::max(most, *std::max_element(map.begin(), map.end()));
    }
  for (const RenderGridCell& c : cells) {
    const ImageError& e = c.figures.error;
    if (c.show_map) {
      sheet.cells.push_back({w, h, refinement_map_pixels(map_of(c), w, h, 1, most),
                             fmt::format("MAP 1-{} AVG {:.2f}", most, c.stats.samples_per_pixel)});
    } else {
      sheet.cells.push_back({w, h, level_pixels(c.image),
                             fmt::format("RMSE {:.2f} MAX {}", e.rmse, e.max_deviation),
                             c.image.channels});
    }
    const std::string spp = c.adaptive ? fmt::format("{:.2f}", c.stats.samples_per_pixel)
                                       : format_cost(c.stats.samples_per_pixel);
    if (c.show_map) continue;  // the same rendering as its image's cell: the table has it
    table += fmt::format("| {} | {} | {} |", c.row, c.column, spp);
    if (lookups) table += fmt::format(" {:.2f} |", c.stats.lookups_per_pixel);
    if (refined)
      table += c.adaptive ? fmt::format(" {:.1f}% |", 100 * c.adaptive->refined_fraction) : " - |";
    table += fmt::format(" {:.3f} | {} | {} | {:.4f} |\n", e.rmse, e.max_deviation,
                         ssim_text(c.figures), c.figures.flip);
  }
  const SheetRaster r = compose_sheet(sheet);
  if (r.channels == 3)
    write_png_rgb(o.output, r.width, r.height, r.pixels);
  else
    write_png_gray(o.output, r.width, r.height, r.pixels);
  const std::string heading =
      fmt::format("{}{} {}x{}: against {} jittered samples per pixel with {}\n\n", o.scene,
                  o.texture.empty() ? "" : " with texture " + o.texture, w, h, s.reference.samples,
                  make_filter(s.reference.filter).name());
  if (!o.table.empty()) write_output(o.table, heading + table, out);
  if (!o.json) {
    out << heading + table;
    return;
  }
  out << json_text(render_grid_json(o.scene, o.texture, w, h, s.reference, cells));
}

// The squared-error histogram as CSV and as a plot.
void write_histogram(const Options& o, const ImageError& e, std::ostream& out) {
  const std::string& what = o.pattern.empty() ? o.generator : o.pattern;
  std::string csv = "deviation,count,contribution\n";
  LineSeries line{what, {}, {}};
  for (int i = 0; i < 256; ++i) {
    csv += fmt::format("{},{},{:.6g}\n", i, e.count[i], e.contribution[i]);
    if (i >= 1 && i <= std::max(1, e.max_deviation)) {
      line.x.push_back(i);
      line.y.push_back(e.contribution[i]);
    }
  }
  if (!o.histogram.empty()) write_output(o.histogram, csv, out);
  if (!o.histogram_svg.empty())
    write_output(o.histogram_svg,
                 line_plot_svg({"Squared-error histogram C(i) i^2 / n (Hasselgren Eq. 1)",
                                "deviation i (0-255)",
                                "C(i) i^2 / n",
                                {},
                                0,
                                0,
                                true},
                               {line}),
                 out);
}

RenderSettings single_settings(const Options& o, int w, int h) {
  RenderSettings s;
  s.width = w;
  s.height = h;
  if (!o.pattern.empty()) s.sampling.pattern = resolve_pattern(o.pattern);
  s.sampling.generator = o.generator;
  s.sampling.samples = o.samples;
  s.sampling.seed = o.seed;
  if (!o.filter.empty()) s.filter = make_filter(o.filter);
  const RenderOptions options = render_options(o);
  s.sampling.shading = options.shading();
  s.adaptive = options.adaptive_settings(s.sampling);
  s.measure = o.measure || o.json || !o.error_png.empty() || !o.histogram.empty() ||
              !o.histogram_svg.empty() || !o.reference_png.empty();
  s.reference = reference_settings(o);
  validate(s);  // the library's one check, before any work
  return s;
}

void run_single(const Options& o, std::ostream& out) {
  const auto [w, h] = parse_size(o.size, "--size", kMaxImageSide);
  for (const std::string* f : {&o.output, &o.error_png, &o.reference_png, &o.refinement_map})
    if (!f->empty() && !f->ends_with(".png")) throw Error(fmt::format("'{}' must end in .png", *f));
  const Scene scene = make_view_scene(o, w, h);
  const RenderSettings s = single_settings(o, w, h);
  const RenderResult r = render_study(scene, s, o.reference.source(/*progress=*/true));
  if (!o.output.empty()) write_png_image(o.output, r.image);
  if (!o.refinement_map.empty()) {
    const GreyRaster map = refinement_map_with_legend(r.adaptive->samples, w, h);
    write_png_gray(o.refinement_map, map.width, map.height, map.pixels);
  }
  const std::string filter = s.filter ? s.filter->name() : "the pattern's weights";
  std::string text = fmt::format("{} {}x{}, {} with {}: {} samples per pixel\n", o.scene, w, h,
                                 o.pattern.empty() ? o.generator : o.pattern, filter,
                                 r.adaptive ? fmt::format("{:.3f}", r.stats.samples_per_pixel)
                                            : format_cost(r.stats.samples_per_pixel));
  if (!s.sampling.shading.exact() || !o.texture.empty())
    text += fmt::format(
        "{} through {}: {:.2f} texture lookups and {:.2f} shadings per pixel\n",
        s.sampling.shading.mode == ShadingMode::supersample ? "supersampled" : "multisampled",
        s.sampling.shading.texture.name, r.stats.lookups_per_pixel, r.stats.shadings_per_pixel);
  if (r.adaptive)
    text += fmt::format("adaptive ({} > {}): {:.1f}% of pixels refined, {} scene evaluations\n",
                        o.adaptive, s.adaptive->threshold, 100 * r.adaptive->refined_fraction,
                        r.adaptive->evaluations);
  const JsonObject js =
      render_json(o.scene, scene, o.texture, o.pattern.empty() ? o.generator : o.pattern, s, r);
  if (r.figures) {
    const ImageError& e = r.figures->error;
    text += fmt::format(
        "against {} jittered samples per pixel with {}: RMSE {:.3f}, max deviation {}, SSIM {}, "
        "FLIP {:.4f}\n",
        s.reference.samples, make_filter(s.reference.filter).name(), e.rmse, e.max_deviation,
        ssim_text(*r.figures), r.figures->flip);
    if (!o.error_png.empty())
      write_png_gray(o.error_png, w, h, error_pixels(r.image, *r.reference));
    if (!o.reference_png.empty()) write_png_image(o.reference_png, *r.reference);
    write_histogram(o, e, out);
  } else {
    text +=
        "(add --measure to measure it against the dense reference: RMSE, max deviation, SSIM)\n";
  }
  out << (o.json ? json_text(js) : text);
}

// --sequence: `frames` frames of the scene, each sampled with its phase and
// accumulated (temporal/engine/taa_render.h).
void run_temporal(const Options& o, std::ostream& out) {
  if (!o.pattern.empty() || !o.generator.empty() || o.grid || !o.adaptive.empty() ||
      !o.filter.empty())
    throw Error(
        "--sequence renders the sequence's frames with their own weights (or --resolve): "
        "give no --pattern, --generator, --filter, --grid or --adaptive");
  const auto [w, h] = parse_size(o.size, "--size", kMaxImageSide);
  if (!o.output.empty() && !o.output.ends_with(".png"))
    throw Error(fmt::format("'{}' must end in .png", o.output));
  const Scene scene = make_view_scene(o, w, h);
  const Sequence s = resolve_sequence(o.sequence);
  const Accumulation model = o.model.make();
  TaaScenes scenes;
  scenes.scene_at = [&](int) { return scene; };
  scenes.reference_frame = [](int) { return kStillFrame; };  // the single rendering's reference
  scenes.width = w;
  scenes.height = h;
  scenes.frames = o.frames > 0 ? o.frames : s.period();
  scenes.reference = reference_settings(o);
  Image last;
  const TaaResult r = render_taa(
      scenes, s, model, !o.cut, [&](int, const Image& img) { last = img; }, o.reference.source());
  if (!o.output.empty()) write_png_image(o.output, last);
  if (o.json) {
    JsonObject js = json_report("render");
    js.update(JsonObject{{"scene", o.scene},
                         {"width", w},
                         {"height", h},
                         {"sequence", s.name},
                         {"model", o.model.text()},
                         {"steady", !o.cut},
                         {"frames", scenes.frames},
                         {"rmse", r.total.rmse},
                         {"max_deviation", r.total.max_deviation},
                         {"mean_ssim", r.mean_ssim ? JsonObject(*r.mean_ssim) : nullptr},
                         {"mean_flip", r.mean_flip},
                         {"flicker", r.flicker}});
    out << json_text(js);
    return;
  }
  out << fmt::format(
      "{} {}x{}, {} under {}, {} frames{}: RMSE {:.3f}, max deviation {}, mean SSIM {}, "
      "mean FLIP {:.4f}, flicker {:.3f} levels per pixel and frame\n",
      o.scene, w, h, s.name, o.model.text(), scenes.frames,
      o.cut ? " from a cut" : " in steady state", r.total.rmse, r.total.max_deviation,
      r.mean_ssim ? fmt::format("{:.4f}", *r.mean_ssim) : "-", r.mean_flip, r.flicker);
}

// render's modes: one rendering (adaptive or not), a contact sheet, a
// sequence accumulated over a still scene. What each takes, and what to give
// instead of what it does not.
OptionModes render_option_modes() {
  const std::vector<std::string> single = {
      "pattern",        "generator", "samples",       "filter",  "reference",
      "error",          "histogram", "histogram-svg", "mode",    "shading-point",
      "texture-filter", "lod",       "mipmap",        "measure", "adaptive"};
  const std::vector<std::string> refinement = {"threshold", "max-depth", "max-samples",
                                               "per-square", "refinement-map"},
                                 sheet = {"rows", "columns", "zoom", "table"},
                                 temporal = {"model",   "alpha",  "window",
                                             "resolve", "frames", "cut"};
  std::vector<std::string> adaptive = single;
  adaptive.insert(adaptive.end(), refinement.begin(), refinement.end());
  // What to give instead: `instead` for every option of `options`.
  const auto each = [](std::map<std::string, std::string>& to,
                       const std::vector<std::string>& options, const std::string& instead) {
    for (const std::string& o : options) to[o] = instead;
  };
  std::map<std::string, std::string> not_single, not_grid, not_temporal;
  each(not_single, refinement, "add --adaptive CRITERION");
  each(not_single, sheet, "add --grid");
  each(not_single, temporal, "add --sequence S for temporal accumulation");
  each(not_grid, adaptive,
       "a sheet takes its samplings from --rows and its filters from --columns, each with "
       "+KEY=VALUE options");
  each(not_grid, temporal, "add --sequence S (without --grid) for temporal accumulation");
  each(not_temporal, adaptive,
       "a sequence's frames render with their own weights (or --resolve F) and are always "
       "measured");
  each(not_temporal, sheet, "a sheet renders no sequence");
  OptionModes t;
  t.command = "render";
  t.selectors = {"grid", "sequence", "adaptive"};
  t.shared = {"size",
              "rotate",
              "scale",
              "translate",
              "seed",
              "output",
              "reference-samples",
              "reference-filter",
              "cache",
              "no-cache",
              "texture",
              "json",
              "grid",
              "sequence"};
  std::map<std::string, std::string> not_adaptive = not_single;
  for (const std::string& a : refinement) not_adaptive.erase(a);
  t.modes = {
      {"the single-rendering mode", single, not_single, {"spiral", "--pattern", "rgss"}},
      {"the adaptive mode (--adaptive)",
       adaptive,
       not_adaptive,
       {"spiral", "--pattern", "rgss", "--adaptive", "contrast"}},
      {"the sheet mode (--grid)", sheet, not_grid, {"spiral", "--grid", "-o", "sheet.png"}},
      {"the temporal mode (--sequence)",
       temporal,
       not_temporal,
       {"spiral", "--sequence", "halton:frames=4"}},
  };
  return t;
}

}  // namespace

Action add_render_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "render a test scene with a pattern and filter");
  auto o = std::make_shared<Options>();
  cmd->add_option("scene", o->scene,
                  "checkerboard, circles, sliver, spiral, zoneplate, disc, halfplane (with "
                  ":key=value parameters, see aapat list) or a .json scene file")
      ->required();
  cmd->add_option("--pattern", o->pattern, "catalog pattern or pattern file, tiled over the image");
  cmd->add_option("--generator", o->generator, "per-pixel generator instead, e.g. jittered");
  cmd->add_option("--samples", o->samples, "samples per pixel for --generator")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxSamplesPerPixel));
  cmd->add_option("--filter", o->filter,
                  "reconstruct with this filter's normalized weights (default: the pattern's own)");
  cmd->add_option("--size", o->size, "WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--rotate", o->rotate, "rotate the scene about the image centre (degrees)");
  cmd->add_option("--scale", o->scale, "scale the scene about the image centre");
  cmd->add_option("--translate", o->translate, "move the scene by X,Y pixels (after rotating)");
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("-o,--output", o->output, "the rendering, or with --grid the sheet (.png)");
  cmd->add_option("--reference", o->reference_png, "the dense reference image (.png)");
  cmd->add_option("--error", o->error_png, "error image against the reference (.png; black = 10%)");
  cmd->add_option("--histogram", o->histogram, "squared-error histogram C(i) i^2 / n (.csv)");
  cmd->add_option("--histogram-svg", o->histogram_svg, "the same histogram as a plot (.svg)");
  add_reference_options(cmd, o->reference, 1024);
  cmd->add_option("--texture", o->texture,
                  "a texture on the checkerboard's ground or a scene file's polygons with \"uv\": "
                  "a .png file or checker, stripes, zoneplate, noise (aapat list)");
  cmd->add_option("--mode", o->mode,
                  "supersample (every sample shaded) or multisample (coverage "
                  "per sample, shading once per pixel and primitive)");
  cmd->add_option("--shading-point", o->shading_point,
                  "multisample: shade at the pixel centre or the centroid of the covered samples");
  cmd->add_option("--texture-filter", o->texture_filter,
                  "nearest, bilinear, mip-nearest, mip-bilinear, trilinear, aniso:probes=8");
  cmd->add_option("--lod", o->lod, "the mipmap level from the Jacobian: max or root-sum-squares");
  cmd->add_option("--mipmap", o->mipmap, "the pyramid: box (2x2 mean) or gaussian");
  cmd->add_option("--adaptive", o->adaptive,
                  "refine adaptively from --pattern/--generator (1-5 samples per pixel) where the "
                  "criterion exceeds --threshold: contrast, variance, neighbours, primitive");
  cmd->add_option("--threshold", o->threshold, "--adaptive: the criterion's threshold (0.1)");
  cmd->add_option("--max-depth", o->max_depth, "--adaptive: squares down to 2^-D pixel (3)");
  cmd->add_option("--max-samples", o->max_samples, "--adaptive: samples per pixel at most (64)");
  cmd->add_option("--per-square", o->per_square, "--adaptive: samples each new square holds (2)");
  cmd->add_option("--refinement-map", o->refinement_map,
                  "--adaptive: samples per pixel as an image with a legend (.png)");
  cmd->add_flag("--grid", o->grid, "a contact sheet of --rows x --columns with the error figures");
  cmd->add_option("--rows", o->rows,
                  "--grid rows: GENERATOR@N (per-pixel, N samples) or patterns, each with "
                  "+KEY=VALUE options (mode, shading-point, texture-filter, lod, mipmap, adaptive, "
                  "threshold, max-depth, max-samples, per-square, show=map)")
      ->capture_default_str();
  cmd->add_option("--columns", o->columns,
                  "--grid columns: filters, or 'weights' (the pattern's), with the rows' +options")
      ->capture_default_str();
  cmd->add_option("--zoom", o->zoom, "--grid: draw each pixel as ZOOM x ZOOM")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxSheetZoom));
  cmd->add_option("--table", o->table, "--grid: also write the error table (markdown)");
  cmd->add_flag("--json", o->json, "print the figures as JSON");
  cmd->add_flag("--measure", o->measure,
                "measure the image against the dense reference (RMSE, max deviation, SSIM)");
  cmd->add_option("--sequence", o->sequence,
                  "temporal mode: a sequence file or generator spec, its frames accumulated by "
                  "--model over the static scene (docs/temporal.md)");
  o->model.add_to(cmd);
  cmd->add_option("--frames", o->frames, "temporal mode: frames rendered (0: the period)")
      ->check(CLI::Range(0, kMaxTaaFrames));
  cmd->add_flag("--cut", o->cut, "temporal mode: start from a camera cut (default: steady state)");
  enforce_option_modes(cmd, render_option_modes(), [cmd] {
    return cmd->get_option("--grid")->count() > 0       ? size_t{2}
           : cmd->get_option("--sequence")->count() > 0 ? size_t{3}
           : cmd->get_option("--adaptive")->count() > 0 ? size_t{1}
                                                        : size_t{0};
  });
  return [o](std::ostream& out) {
    if (!o->sequence.empty()) return run_temporal(*o, out);
    if (o->cut || o->frames)
      throw Error("--cut and --frames belong to the temporal mode: add --sequence");
    o->grid ? run_grid(*o, out) : run_single(*o, out);
  };
}

}  // namespace aapat
