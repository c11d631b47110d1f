// `aapat animate` and `aapat table2`: animations rendered with a pattern
// against a dense reference (Hasselgren et al. Sec. 6.1), and Hasselgren
// Table 2's RMSE and max-deviation columns re-measured on the translating circle.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/commands.h"
#include "cli/progress.h"
#include "core/filter_catalog.h"
#include "core/metric.h"
#include "io/pattern_json.h"
#include "io/png_image.h"
#include "render/animation.h"

namespace aapat {
namespace {

void add_animation_options(CLI::App* cmd, AnimationSettings& a) {
  cmd->add_option("--size", a.width, "width and height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--frames", a.frames, "frames")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--reference-samples", a.reference_samples,
                  "jittered samples per pixel (a square)")
      ->capture_default_str()
      ->check(CLI::Range(1, 65536));
  cmd->add_option("--seed", a.seed, "random seed of the reference")->capture_default_str();
}

}  // namespace

Action add_animate_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("animate", "render an animation with a pattern against a reference");
  struct Options {
    AnimationSettings a;
    std::string pattern, filter, frames_dir, histogram;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("animation", o->a.animation, "circle (translating) or triangle (rotating)")
      ->required();
  cmd->add_option("--pattern", o->pattern, "catalog pattern or pattern file")->required();
  cmd->add_option("--filter", o->filter,
                  "reconstruct with this filter (default: the pattern's weights)");
  add_animation_options(cmd, o->a);
  cmd->add_option("--frames-dir", o->frames_dir, "write every frame as frame-NNNN.png here");
  cmd->add_option("--histogram", o->histogram, "squared-error histogram of all frames (.csv)");
  cmd->add_flag("--json", o->json, "print JSON");
  return [o](std::ostream& out) {
    o->a.height = o->a.width;
    Sampling s;
    s.pattern = resolve_pattern(o->pattern);
    std::optional<Filter> filter;
    if (!o->filter.empty()) filter = make_filter(o->filter);
    if (!o->frames_dir.empty()) std::filesystem::create_directories(o->frames_dir);
    Progress bar("animate");
    const ImageError e = animate(o->a, s, filter, [&](int f, const Image& img) {
      if (!o->frames_dir.empty())
        write_png_gray(fmt::format("{}/frame-{:04d}.png", o->frames_dir, f), img.width, img.height,
                       grey_pixels(img));
      bar.update(f + 1, o->a.frames, "");
    });
    if (!o->histogram.empty()) {
      std::string csv = "deviation,count,contribution\n";
      for (int i = 0; i < 256; ++i)
        csv += fmt::format("{},{},{:.6g}\n", i, e.count[i], e.contribution[i]);
      write_output(o->histogram, csv, out);
    }
    if (o->json) {
      out << nlohmann::ordered_json{{"animation", o->a.animation},
                                    {"pattern", o->pattern},
                                    {"frames", o->a.frames},
                                    {"size", o->a.width},
                                    {"rmse", e.rmse},
                                    {"max_deviation", e.max_deviation}}
                 .dump(2)
          << "\n";
      return;
    }
    out << fmt::format("{} animation, {} frames of {}x{}, {}: RMSE {:.3f}, max deviation {}\n",
                       o->a.animation, o->a.frames, o->a.width, o->a.width, o->pattern, e.rmse,
                       e.max_deviation);
  };
}

Action add_table2_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "table2",
      "re-measure Hasselgren Table 2 (E2, RMSE, max deviation) on the translating circle");
  auto a = std::make_shared<AnimationSettings>();
  add_animation_options(cmd, *a);
  return [a](std::ostream& out) {
    a->height = a->width;
    struct Row {
      const char* pattern;
      const char* label;
      double e2, rmse;
      int max_dev;  // Hasselgren et al. Table 2
    };
    const Row rows[] = {{"centroid", "Centroid sampling", 1.256, 9.810, 131},
                        {"diagonal-hasselgren", "Diagonal", 0.692, 6.500, 126},
                        {"hasselgren-a", "Scheme A (FLIPTRI)", 0.554, 7.548, 159},
                        {"hasselgren-b", "Scheme B", 0.531, 5.139, 114},
                        {"hasselgren-c", "Scheme C", 0.527, 4.830, 107},
                        {"hasselgren-d", "Scheme D", 0.497, 5.000, 107},
                        {"hasselgren-e", "Scheme E", 0.488, 4.574, 108},
                        {"quincunx-hasselgren", "Quincunx", 0.484, 4.400, 95},
                        {"hasselgren-f", "Scheme F (FLIPQUAD)", 0.359, 3.759, 76}};
    const Metric metric(make_filter(kDefaultFilter), laine_aila_acuity());
    std::string table;
    Progress bar("table2");
    int done = 0;
    for (const Row& r : rows) {
      Sampling s;
      s.pattern = resolve_pattern(r.pattern);
      const ImageError e = animate(*a, s, std::nullopt);
      table += fmt::format("{:<21} {:>6.3f} ({:.3f})  {:>6.3f} ({:.3f})  {:>4} ({})\n", r.label,
                           metric.evaluate(*s.pattern).e2, r.e2, e.rmse, r.rmse, e.max_deviation,
                           r.max_dev);
      bar.update(++done, static_cast<int>(std::size(rows)), r.pattern);
    }
    out << fmt::format(
        "Hasselgren Table 2 re-measured: translating circle, {} frames of {}x{}, reference {} "
        "jittered samples per pixel with {}\naapat (paper)         E2               RMSE           "
        " "
        "  max dev.\n{}",
        a->frames, a->width, a->width, a->reference_samples,
        make_filter(a->reference_filter).name(), table);
  };
}

}  // namespace aapat
