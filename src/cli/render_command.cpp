// `aapat render SCENE`: an analytic scene sampled with a pattern or a
// per-pixel generator, reconstructed with the pattern's weights or a filter;
// optionally against a dense reference, with the error figures.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/commands.h"
#include "core/filter_catalog.h"
#include "io/line_plot.h"
#include "io/pattern_json.h"
#include "io/png_image.h"
#include "render/image_error.h"
#include "render/renderer.h"

namespace aapat {

Action add_render_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "render a test scene with a pattern and filter");
  struct Options {
    std::string scene, pattern, generator, filter, size = "256x256", output;
    std::string error_png, histogram, histogram_svg, reference_filter = "mitchell";
    int samples = 16, reference_samples = 1024;
    uint64_t seed = 1;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("scene", o->scene,
                  "checkerboard, circles, sliver, spiral, zoneplate, halfplane:...")
      ->required();
  cmd->add_option("--pattern", o->pattern, "catalog pattern or pattern file, tiled over the image");
  cmd->add_option("--generator", o->generator, "per-pixel generator instead, e.g. jittered");
  cmd->add_option("--samples", o->samples, "samples per pixel for --generator")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--filter", o->filter,
                  "reconstruct with this filter's normalized weights (default: the pattern's own)");
  cmd->add_option("--size", o->size, "WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--seed", o->seed, "random seed")->capture_default_str();
  cmd->add_option("-o,--output", o->output, "the rendering (.png)");
  cmd->add_option("--error", o->error_png, "error image against the reference (.png; black = 10%)");
  cmd->add_option("--histogram", o->histogram, "squared-error histogram C(i) i^2 / n (.csv)");
  cmd->add_option("--histogram-svg", o->histogram_svg, "the same histogram as a plot (.svg)");
  cmd->add_option("--reference-samples", o->reference_samples,
                  "jittered samples per pixel of the reference (a square)")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--reference-filter", o->reference_filter, "the reference's filter")
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print the figures as JSON");
  return [o](std::ostream& out) {
    int w = 0, h = 0;
    const auto x = o->size.find('x');
    if (x == std::string::npos)
      throw Error(fmt::format("--size: '{}' is not WIDTHxHEIGHT", o->size));
    w = static_cast<int>(parse_number(o->size.substr(0, x), "--size"));
    h = static_cast<int>(parse_number(o->size.substr(x + 1), "--size"));
    if (o->pattern.empty() == o->generator.empty())
      throw Error("render: give either --pattern or --generator");
    for (const std::string* f : {&o->output, &o->error_png})
      if (!f->empty() && !f->ends_with(".png"))
        throw Error(fmt::format("'{}' must end in .png", *f));
    const Scene scene = make_scene(o->scene, w, h);
    Sampling sampling;
    if (!o->pattern.empty()) sampling.pattern = resolve_pattern(o->pattern);
    sampling.generator = o->generator;
    sampling.samples = o->samples;
    sampling.seed = o->seed;
    std::optional<Filter> filter;
    if (!o->filter.empty()) filter = make_filter(o->filter);
    RenderStats stats;
    const Image image = render(scene, w, h, sampling, filter, &stats);
    if (!o->output.empty()) write_png_gray(o->output, w, h, grey_pixels(image));

    nlohmann::ordered_json js{{"scene", o->scene},
                              {"size", o->size},
                              {"sampling", o->pattern.empty() ? o->generator : o->pattern},
                              {"filter", filter ? filter->name() : "pattern weights"},
                              {"samples_per_pixel", stats.samples_per_pixel}};
    std::string text = fmt::format("{} {}x{}, {} with {}: {} samples per pixel\n", o->scene, w, h,
                                   o->pattern.empty() ? o->generator : o->pattern,
                                   filter ? filter->name() : "the pattern's weights",
                                   format_cost(stats.samples_per_pixel));
    const bool want_reference =
        o->json || !o->error_png.empty() || !o->histogram.empty() || !o->histogram_svg.empty();
    if (want_reference) {
      Sampling ref;
      ref.generator = "jittered";
      ref.samples = o->reference_samples;
      ref.seed = o->seed + 1000003;
      const Image reference =
          render(scene, w, h, ref, make_filter(o->reference_filter), nullptr, image.offset);
      const ImageError e = compare(image, reference);
      js["reference"] = fmt::format("{} jittered samples per pixel, {}", o->reference_samples,
                                    make_filter(o->reference_filter).name());
      js["rmse"] = e.rmse;
      js["max_deviation"] = e.max_deviation;
      text += fmt::format(
          "against {} jittered samples per pixel with {}: RMSE {:.3f}, max deviation {}\n",
          o->reference_samples, make_filter(o->reference_filter).name(), e.rmse, e.max_deviation);
      if (!o->error_png.empty()) write_png_gray(o->error_png, w, h, error_pixels(image, reference));
      std::string csv = "deviation,count,contribution\n";
      LineSeries line{o->pattern.empty() ? o->generator : o->pattern, {}, {}};
      for (int i = 0; i < 256; ++i) {
        csv += fmt::format("{},{},{:.6g}\n", i, e.count[i], e.contribution[i]);
        if (i >= 1 && i <= std::max(1, e.max_deviation)) {
          line.x.push_back(i);
          line.y.push_back(e.contribution[i]);
        }
      }
      if (!o->histogram.empty()) write_output(o->histogram, csv, out);
      if (!o->histogram_svg.empty())
        write_output(o->histogram_svg,
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
    out << (o->json ? js.dump(2) + "\n" : text);
  };
}

}  // namespace aapat
