// `aapat render SCENE`: an analytic scene (or a scene file) sampled with a
// pattern or a per-pixel generator, reconstructed with the pattern's weights
// or a filter; optionally against a dense reference, with the error figures.
// With --grid, rows of samplings x columns of filters in one contact sheet.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <ostream>

#include "cli/commands.h"
#include "cli/reference_options.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/contact_sheet.h"
#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/image_error.h"
#include "aapat/render/renderer.h"
#include "aapat/render/ssim.h"

namespace aapat {
namespace {

struct Options {
  std::string scene, pattern, generator, filter, size = "256x256", output;
  std::string error_png, histogram, histogram_svg, translate, table, reference_png;
  ReferenceOptions reference;
  double rotate = 0, scale = 1;
  int samples = 16, zoom = 1;
  uint64_t seed = 1;
  bool json = false, grid = false;
  std::vector<std::string> rows{"regular@4",  "n-queens@4",  "jittered@4",
                                "regular@16", "n-queens@16", "jittered@16"};
  std::vector<std::string> columns{"box", "tent", "gaussian-half"};
};

// The reference every figure of this run is measured against.
ReferenceSettings reference_settings(const Options& o) {
  ReferenceSettings ref = o.reference.settings;
  ref.seed = o.seed + 1000003;
  return ref;
}

Scene make_view_scene(const Options& o, int w, int h) {
  Scene scene = resolve_scene(o.scene, w, h);
  if (!std::isfinite(o.rotate) || !(o.scale > 1e-6 && o.scale < 1e6))
    throw Error(
        fmt::format("--rotate {} / --scale {}: need a finite angle and a scale in "
                    "(1e-6, 1e6)",
                    o.rotate, o.scale));
  scene.view.pivot = {(w - 1) / 2.0, (h - 1) / 2.0};
  scene.view.rotation_deg = o.rotate;
  scene.view.scale = o.scale;
  if (!o.translate.empty()) {
    const auto parts = split(o.translate);
    if (parts.size() != 2) throw Error(fmt::format("--translate: '{}' is not X,Y", o.translate));
    scene.view.translation = {parse_number(parts[0], "--translate"),
                              parse_number(parts[1], "--translate")};
    if (!(std::abs(scene.view.translation.x) <= 1e7 && std::abs(scene.view.translation.y) <= 1e7))
      throw Error(
          fmt::format("--translate {}: each offset must be within 1e7 pixels", o.translate));
  }
  return scene;
}

// The error figures of one rendering against its reference.
struct Figures {
  ImageError error;
  std::optional<double> ssim_value;
};

Figures measure(const Image& image, const Image& reference) {
  Figures f{compare(image, reference), std::nullopt};
  if (image.width >= kSsimWindow && image.height >= kSsimWindow)
    f.ssim_value = ssim(image, reference);
  return f;
}

std::string ssim_text(const Figures& f) {
  return f.ssim_value ? fmt::format("{:.4f}", *f.ssim_value) : "-";
}

// A grid row: `GENERATOR@N` (a per-pixel generator, N samples) or a pattern.
Sampling row_sampling(const std::string& row, uint64_t seed) {
  Sampling s;
  s.seed = seed;
  if (const auto at = row.rfind('@'); at != std::string::npos) {
    s.generator = row.substr(0, at);
    const double n = parse_number(row.substr(at + 1), fmt::format("--rows {}", row));
    if (!(n >= 1 && n <= 65536) || n != std::floor(n))
      throw Error(
          fmt::format("--rows {}: the sample count must be a whole number in [1, 65536]", row));
    s.samples = static_cast<int>(n);
  } else {
    s.pattern = resolve_pattern(row);
  }
  return s;
}

void run_grid(const Options& o, std::ostream& out) {
  const auto [w, h] = parse_size(o.size, "--size", 16384);
  if (o.output.empty() || !o.output.ends_with(".png"))
    throw Error("render --grid: give the sheet's file with -o SHEET.png");
  const Scene scene = make_view_scene(o, w, h);
  const ReferenceSource references = o.reference.source();
  const ReferenceSettings ref = reference_settings(o);
  std::map<double, Image> reference_at;  // by offset: even footprints shift the image
  ContactSheet sheet{fmt::format("{} {}x{}", o.scene, w, h), o.rows, o.columns, {}, o.zoom};
  std::string table = "| sampling | filter | samples/pixel | RMSE | max dev. | SSIM |\n";
  table += "| --- | --- | ---: | ---: | ---: | ---: |\n";
  JsonObject cells = JsonObject::array();
  for (const std::string& row : o.rows) {
    const Sampling sampling = row_sampling(row, o.seed);
    for (const std::string& column : o.columns) {
      std::optional<Filter> filter;
      if (column != "weights") filter = make_filter(column);
      if (!filter && !sampling.pattern)
        throw Error(
            fmt::format("--columns weights: row '{}' is a generator, which has no weights", row));
      RenderStats stats;
      const Image image = render(scene, w, h, sampling, filter, &stats);
      auto it = reference_at.find(image.offset);
      if (it == reference_at.end())
        it = reference_at.emplace(image.offset, references(scene, w, h, ref, image.offset)).first;
      const Figures f = measure(image, it->second);
      sheet.cells.push_back(
          {w, h, grey_pixels(image),
           fmt::format("RMSE {:.2f} MAX {}", f.error.rmse, f.error.max_deviation)});
      table += fmt::format("| {} | {} | {} | {:.3f} | {} | {} |\n", row, column,
                           format_cost(stats.samples_per_pixel), f.error.rmse,
                           f.error.max_deviation, ssim_text(f));
      JsonObject cell = sampling.pattern ? JsonObject{{"pattern", row}}
                                         : JsonObject{{"generator", sampling.generator},
                                                      {"samples", sampling.samples}};
      cell.update(JsonObject{{"filter", column},
                             {"samples_per_pixel", stats.samples_per_pixel},
                             {"rmse", f.error.rmse},
                             {"max_deviation", f.error.max_deviation},
                             {"ssim", f.ssim_value ? JsonObject(*f.ssim_value) : nullptr}});
      cells.push_back(std::move(cell));
    }
  }
  const GreyRaster r = compose_sheet(sheet);
  write_png_gray(o.output, r.width, r.height, r.pixels);
  const std::string heading =
      fmt::format("{} {}x{}: against {} jittered samples per pixel with {}\n\n", o.scene, w, h,
                  ref.samples, make_filter(ref.filter).name());
  if (!o.table.empty()) write_output(o.table, heading + table, out);
  if (o.json) {
    JsonObject doc = json_report("render");
    doc.update(JsonObject{{"scene", o.scene},
                          {"width", w},
                          {"height", h},
                          {"reference", describe_reference(ref)},
                          {"rows", cells}});
    out << json_text(doc);
  } else {
    out << heading + table;
  }
}

void run_single(const Options& o, std::ostream& out) {
  const auto [w, h] = parse_size(o.size, "--size", 16384);
  if (o.pattern.empty() == o.generator.empty())
    throw Error("render: give either --pattern or --generator");
  for (const std::string* f : {&o.output, &o.error_png, &o.reference_png})
    if (!f->empty() && !f->ends_with(".png")) throw Error(fmt::format("'{}' must end in .png", *f));
  const Scene scene = make_view_scene(o, w, h);
  Sampling sampling;
  if (!o.pattern.empty()) sampling.pattern = resolve_pattern(o.pattern);
  if (!o.generator.empty()) {
    make_point_generator(o.generator);  // an unknown generator is named before anything else
    if (o.filter.empty())
      throw Error(fmt::format(
          "--generator {}: per-pixel points have no weights of their own; give a --filter",
          o.generator));
  }
  sampling.generator = o.generator;
  sampling.samples = o.samples;
  sampling.seed = o.seed;
  std::optional<Filter> filter;
  if (!o.filter.empty()) filter = make_filter(o.filter);
  RenderStats stats;
  const Image image = render(scene, w, h, sampling, filter, &stats);
  if (!o.output.empty()) write_png_gray(o.output, w, h, grey_pixels(image));

  const std::string& what = o.pattern.empty() ? o.generator : o.pattern;
  JsonObject js = json_report("render");
  js.update(JsonObject{{"scene", o.scene}, {"width", w}, {"height", h}});
  if (sampling.pattern)
    js["pattern"] = o.pattern;
  else
    js.update(JsonObject{{"generator", o.generator}, {"samples", o.samples}});
  js.update(JsonObject{{"filter", filter ? filter->name() : "pattern weights"},
                       {"samples_per_pixel", stats.samples_per_pixel}});
  std::string text = fmt::format("{} {}x{}, {} with {}: {} samples per pixel\n", o.scene, w, h,
                                 what, filter ? filter->name() : "the pattern's weights",
                                 format_cost(stats.samples_per_pixel));
  const bool want_reference = o.json || !o.error_png.empty() || !o.histogram.empty() ||
                              !o.histogram_svg.empty() || !o.reference_png.empty();
  if (want_reference) {
    const ReferenceSettings ref = reference_settings(o);
    const Image reference = o.reference.source()(scene, w, h, ref, image.offset);
    const Figures f = measure(image, reference);
    const ImageError& e = f.error;
    const std::string ref_name = make_filter(ref.filter).name();
    js["reference"] = describe_reference(ref);
    js["rmse"] = e.rmse;
    js["max_deviation"] = e.max_deviation;
    js["ssim"] = f.ssim_value ? JsonObject(*f.ssim_value) : nullptr;
    text += fmt::format(
        "against {} jittered samples per pixel with {}: RMSE {:.3f}, max deviation {}, SSIM {}\n",
        ref.samples, ref_name, e.rmse, e.max_deviation, ssim_text(f));
    if (!o.error_png.empty()) write_png_gray(o.error_png, w, h, error_pixels(image, reference));
    if (!o.reference_png.empty()) write_png_gray(o.reference_png, w, h, grey_pixels(reference));
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
  out << (o.json ? json_text(js) : text);
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
      ->check(CLI::Range(1, 65536));
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
  cmd->add_flag("--grid", o->grid, "a contact sheet of --rows x --columns with the error figures");
  cmd->add_option("--rows", o->rows, "--grid rows: GENERATOR@N (per-pixel, N samples) or patterns")
      ->capture_default_str();
  cmd->add_option("--columns", o->columns, "--grid columns: filters, or 'weights' (the pattern's)")
      ->capture_default_str();
  cmd->add_option("--zoom", o->zoom, "--grid: draw each pixel as ZOOM x ZOOM")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  cmd->add_option("--table", o->table, "--grid: also write the error table (markdown)");
  cmd->add_flag("--json", o->json, "print the figures as JSON");
  // Options of one mode are refused in the other, before any work.
  const std::vector<const CLI::Option*> single_only = {
      cmd->get_option("--pattern"),   cmd->get_option("--generator"),
      cmd->get_option("--samples"),   cmd->get_option("--filter"),
      cmd->get_option("--reference"), cmd->get_option("--error"),
      cmd->get_option("--histogram"), cmd->get_option("--histogram-svg")};
  const std::vector<const CLI::Option*> grid_only = {
      cmd->get_option("--rows"), cmd->get_option("--columns"), cmd->get_option("--zoom"),
      cmd->get_option("--table")};
  return [o, single_only, grid_only](std::ostream& out) {
    for (const CLI::Option* opt : o->grid ? single_only : grid_only)
      if (opt->count() > 0)
        throw Error(o->grid ? fmt::format("render --grid: {} is for a single rendering; a sheet "
                                          "takes its samplings from --rows and filters from "
                                          "--columns",
                                          opt->get_name())
                            : fmt::format("render: {} is for a --grid sheet", opt->get_name()));
    o->grid ? run_grid(*o, out) : run_single(*o, out);
  };
}

}  // namespace aapat
