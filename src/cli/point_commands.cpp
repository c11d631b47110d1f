// `aapat generate`, `aapat discrepancy` and `aapat spectrum`: point sets,
// their discrepancies and their Fourier power spectra.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <ostream>
#include <random>
#include <set>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/spectrum.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "aapat/core/text.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/png_image.h"
#include "aapat/io/point_set_file.h"

namespace aapat {
namespace {

struct PointSource {
  std::string source;
  int n = 16;
  uint64_t seed = 1;

  void add_to(CLI::App* cmd) {
    cmd->add_option("source", source, "generator spec (see `aapat list`) or a .csv / .json file")
        ->required();
    cmd->add_option("--n", n, "points")->capture_default_str()->check(CLI::Range(1, 1000000));
    add_seed_option(cmd, seed, "random seed");
  }
  bool is_file() const { return source.ends_with(".csv") || source.ends_with(".json"); }
  // Realization r of the source (a file has only one).
  std::vector<Vec2> points(int realization = 0) const {
    if (is_file()) return load_point_set(source);
    return generate_points(source, n, seed + static_cast<uint64_t>(realization));
  }
};

// The exact 2D spectrum's work: points x frequencies x realizations.
constexpr double kMaxSpectrumTerms = 68719476736.0;  // 2^36

// 1D point sets for Goss & Wu's Figure 8: n points with unit mean spacing.
std::vector<double> points_1d(const std::string& kind, int n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> xs;
  if (kind == "jittered") {
    for (int i = 0; i < n; ++i) xs.push_back(i + u(rng));
  } else if (kind == "poisson") {
    // Dart throwing on [0, n) with minimum distance 0.6 (on the circle).
    std::set<double> placed;
    const double d = 0.6;
    while (static_cast<int>(placed.size()) < n) {
      const double x = u(rng) * n;
      auto hi = placed.lower_bound(x);
      auto dist = [&](double a) {
        const double t = std::abs(a - x);
        return std::min(t, n - t);
      };
      bool ok = true;
      if (hi != placed.end()) ok = ok && dist(*hi) >= d;
      if (hi != placed.begin()) ok = ok && dist(*std::prev(hi)) >= d;
      if (!placed.empty()) ok = ok && dist(*placed.begin()) >= d && dist(*placed.rbegin()) >= d;
      if (ok) placed.insert(x);
    }
    xs.assign(placed.begin(), placed.end());
  } else {
    throw Error(fmt::format("--1d: '{}' is not poisson or jittered", kind));
  }
  return xs;
}

}  // namespace

Action add_generate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("generate", "generate a point set or a pixel pattern");
  auto src = std::make_shared<PointSource>();
  auto output = std::make_shared<std::string>();
  auto tile = std::make_shared<int>(0);
  auto json = std::make_shared<bool>(false);
  src->add_to(cmd);
  cmd->add_flag("--json", *json, "print the points as JSON (docs/json.md) instead of CSV");
  cmd->add_option("-o,--output", *output,
                  "a .csv point set or a .json pattern (P(1,1,n)); default: CSV on stdout");
  cmd->add_option(
      "--tile", *tile,
      "with a .json output: a K x K tile of pixel sets, each generated anew: P(K^2,1,n)");
  return [src, output, tile, json](std::ostream& out) {
    if (src->is_file()) throw Error("generate: give a generator, not a file");
    if (*json && !output->empty())
      throw Error("--json prints the points; it does not go with -o (the file has them)");
    if (*tile > 0) {
      if (!output->ends_with(".json"))
        throw Error("--tile: write the tile as a pattern file (-o file.json)");
      Pattern p = tile_pattern(src->source, src->n, src->seed, *tile);
      p.description = fmt::format("{} x {} tile of {} points per pixel from {}", *tile, *tile,
                                  src->n, src->source);
      p.provenance = {{"generator", src->source},
                      {"n", std::to_string(src->n)},
                      {"seed", std::to_string(src->seed)},
                      {"tile", std::to_string(*tile)}};
      save_pattern_file(p, *output);
      out << fmt::format("wrote {} ({})\n", *output, family(p));
      return;
    }
    const auto points = src->points();
    if (*json) {
      JsonObject doc = json_report("generate");
      doc.update(JsonObject{{"source", src->source}, {"n", points.size()}, {"seed", src->seed}});
      JsonObject rows = JsonObject::array();
      for (const Vec2& v : points) rows.push_back({{"x", v.x}, {"y", v.y}});
      doc["rows"] = std::move(rows);
      out << json_text(doc);
    } else if (output->empty() || *output == "-") {
      out << point_csv(points);
    } else if (output->ends_with(".json")) {
      Pattern p = points_to_pattern(
          points,
          fmt::format("{}-{}", src->source.substr(0, src->source.find(':')), points.size()));
      p.description = fmt::format("{} points from {}", points.size(), src->source);
      p.provenance = {{"generator", src->source},
                      {"n", std::to_string(points.size())},
                      {"seed", std::to_string(src->seed)}};
      save_pattern_file(p, *output);
      out << fmt::format("wrote {} ({} points, {})\n", *output, points.size(), family(p));
    } else if (output->ends_with(".csv")) {
      write_output(*output, point_csv(points), out);
      out << fmt::format("wrote {} ({} points)\n", *output, points.size());
    } else {
      throw Error(fmt::format("--output: '{}' must end in .csv or .json", *output));
    }
  };
}

Action add_discrepancy_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("discrepancy", "L2-star, star and edge discrepancy of a point set");
  auto src = std::make_shared<PointSource>();
  auto json = std::make_shared<bool>(false);
  src->add_to(cmd);
  cmd->add_flag("--json", *json, "print JSON");
  return [src, json](std::ostream& out) {
    const auto points = src->points();
    double l2 = 0;  // l2_star_discrepancy refuses too many points before any work
    StarDiscrepancy star;
    EdgeDiscrepancy edge;
    {
      Progress bar("discrepancy");
      bar.update(0, 3, "L2-star");
      l2 = l2_star_discrepancy(points);
      bar.update(1, 3, "star");
      star = star_discrepancy(points);
      bar.update(2, 3, "edge");
      edge = edge_discrepancy(points, 720, [&](int done, int total) {
        if (done % 16 == 0) bar.update(2, 3, fmt::format("edge {}/{}", done, total));
      });
    }
    if (*json) {
      JsonObject doc = json_report("discrepancy");
      doc.update(JsonObject{{"source", src->source},
                            {"points", points.size()},
                            {"l2_star", l2},
                            {"star_lower", star.lower},
                            {"star_upper", star.upper},
                            {"star_exact", star.exact},
                            {"edge", edge.value},
                            {"edge_normal_deg", edge.normal_deg}});
      out << json_text(doc);
      return;
    }
    out << fmt::format("{} ({} points)\n  L2-star discrepancy  {:.6f}\n", src->source,
                       points.size(), l2);
    if (star.exact)
      out << fmt::format("  star discrepancy     {:.6f} (exact)\n", star.upper);
    else
      out << fmt::format("  star discrepancy     in [{:.6f}, {:.6f}] (grid bounds)\n", star.lower,
                         star.upper);
    out << fmt::format("  edge discrepancy     {:.6f} (worst half-plane normal at {:g} degrees)\n",
                       edge.value, edge.normal_deg);
  };
}

Action add_spectrum_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("spectrum", "Fourier power spectrum of a point set (2D, or 1D with --1d)");
  struct Options {
    PointSource src;
    int size = 256, realizations = 1, frequencies = 131072;
    double max_frequency = 4;
    std::string png, csv, svg, one_d;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("source", o->src.source, "generator spec or a .csv / .json file (2D)");
  cmd->add_option("--n", o->src.n, "points")->capture_default_str()->check(CLI::Range(1, 1000000));
  add_seed_option(cmd, o->src.seed, "random seed");
  cmd->add_option("--size", o->size, "frequencies per axis, -size/2 .. size/2-1")
      ->capture_default_str()
      ->check(CLI::Range(8, 2048));
  cmd->add_option("--realizations", o->realizations,
                  "point sets averaged (seeds seed, seed+1, ...)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("-o,--output", o->png,
                  "the 2D spectrum as a PNG (grey = power / 2, DC at the centre)");
  cmd->add_option("--csv", o->csv, "radial average (2D) or the spectrum (1D) as CSV");
  cmd->add_option("--svg", o->svg, "radial average (2D) or the spectrum (1D) as an SVG plot");
  cmd->add_option("--1d", o->one_d,
                  "Goss-Wu Fig. 8: 1D 'poisson' or 'jittered' with unit mean spacing");
  cmd->add_option("--frequencies", o->frequencies, "1D: frequencies evaluated")
      ->capture_default_str()
      ->check(CLI::Range(16, 10000000));
  cmd->add_flag("--json", o->json, "print the radial average (2D) or the spectrum (1D) as JSON");
  cmd->add_option("--max-frequency", o->max_frequency,
                  "1D: highest frequency, cycles per mean spacing")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1000.0));
  return [o](std::ostream& out) {
    if (!o->one_d.empty()) {
      if (!o->png.empty())
        throw Error(
            "-o writes the 2D spectrum as a PNG; with --1d write --csv or --svg (a 1D spectrum "
            "is a curve)");
      if (!o->src.source.empty())
        throw Error(
            fmt::format("--1d draws its own 1D points; drop the source '{}'", o->src.source));
      // One curve per kind in a comma list, in one table and one plot.
      std::vector<std::string> kinds;
      for (std::string_view k : split(o->one_d)) kinds.emplace_back(trim(k));
      std::vector<std::vector<double>> powers;
      std::vector<LineSeries> lines;
      size_t count = 0;
      for (const auto& kind : kinds) {
        const auto xs = points_1d(kind, o->src.n, o->src.seed);
        count = xs.size();
        powers.push_back(power_spectrum_1d(xs, o->frequencies, o->max_frequency));
        const auto& power = powers.back();
        // Plot the mean of each bin of frequencies (an SVG of 128K points is no
        // use), from past the DC peak's main lobe (|f| < 2 / length) on.
        const int bins = std::min(o->frequencies, 2000);
        const int first =
            static_cast<int>(std::ceil(2.0 / xs.size() / o->max_frequency * o->frequencies));
        LineSeries line{fmt::format("{} ({} points)", kind, xs.size()), {}, {}};
        for (int b = 0; b < bins; ++b) {
          const int k0 = std::max(first, b * o->frequencies / bins),
                    k1 = (b + 1) * o->frequencies / bins;
          if (k1 <= k0) continue;
          double sum = 0;
          for (int k = k0; k < k1; ++k) sum += power[k];
          line.x.push_back((k0 + k1) / 2.0 * o->max_frequency / o->frequencies);
          line.y.push_back(sum / std::max(1, k1 - k0));
        }
        lines.push_back(std::move(line));
      }
      std::string csv = "frequency";
      for (const auto& kind : kinds) csv += "," + kind;
      csv += "\n";
      for (int k = 0; k < o->frequencies; ++k) {
        csv += fmt::format("{:.6g}", k * o->max_frequency / o->frequencies);
        for (const auto& power : powers) csv += fmt::format(",{:.6g}", power[k]);
        csv += "\n";
      }
      if (!o->csv.empty()) write_output(o->csv, csv, out);
      if (o->json) {
        JsonObject doc = json_report("spectrum");
        doc.update(JsonObject{{"dimensions", 1},
                              {"kinds", kinds},
                              {"points", count},
                              {"seed", o->src.seed},
                              {"frequencies", o->frequencies},
                              {"max_frequency", o->max_frequency}});
        JsonObject rows = JsonObject::array();
        for (int k = 0; k < o->frequencies; ++k) {
          JsonObject row{{"frequency", k * o->max_frequency / o->frequencies}};
          for (size_t i = 0; i < kinds.size(); ++i) row[kinds[i]] = powers[i][k];
          rows.push_back(std::move(row));
        }
        doc["rows"] = std::move(rows);
        out << json_text(doc);
      }
      if (!o->svg.empty())
        write_output(
            o->svg,
            line_plot_svg({fmt::format("1D power spectra, {} points (Goss-Wu Fig. 8)", count),
                           "frequency (cycles per mean spacing)",
                           "power",
                           {},
                           0,
                           o->max_frequency,
                           true},
                          lines),
            out);
      if (!o->json)
        out << fmt::format("1D {}: {} points, {} frequencies up to {}\n", o->one_d, count,
                           o->frequencies, o->max_frequency);
      return;
    }
    if (o->src.source.empty()) throw Error("spectrum: give a generator or a point file (or --1d)");
    // The exact spectrum costs points x size^2 per realization.
    const double work = static_cast<double>(o->src.n) * o->size * o->size * o->realizations;
    if (!o->src.is_file() && work > kMaxSpectrumTerms)
      throw Error(fmt::format(
          "spectrum: {} points x {}^2 frequencies x {} realizations = {:.3g} terms exceed the "
          "limit of {:.3g}; lower --n, --size or --realizations",
          o->src.n, o->size, o->realizations, work, kMaxSpectrumTerms));
    Spectrum2D mean;
    size_t points = 0;
    {
      Progress bar("spectrum");
      const int realizations = o->src.is_file() ? 1 : o->realizations;
      for (int r = 0; r < realizations; ++r) {
        const auto pts = o->src.points(r);
        points = pts.size();
        if (static_cast<double>(points) * o->size * o->size > kMaxSpectrumTerms)
          throw Error(
              fmt::format("spectrum: {} points x {}^2 frequencies exceed the limit of {:.3g} terms",
                          points, o->size, kMaxSpectrumTerms));
        accumulate(mean, power_spectrum(pts, o->size), 1.0 / realizations);
        bar.update(r + 1, realizations, "");
      }
    }
    const RadialProfile radial = radial_average(mean);
    if (!o->png.empty()) {
      if (!o->png.ends_with(".png"))
        throw Error(fmt::format("--output: '{}' must end in .png", o->png));
      std::vector<uint8_t> pixels(static_cast<size_t>(o->size) * o->size);
      for (int row = 0; row < o->size; ++row)  // top row = highest v
        for (int col = 0; col < o->size; ++col) {
          const double p = mean.power[static_cast<size_t>(o->size - 1 - row) * o->size + col];
          pixels[static_cast<size_t>(row) * o->size + col] =
              static_cast<uint8_t>(std::lround(255 * std::min(1.0, p / 2)));
        }
      write_png_gray(o->png, o->size, o->size, pixels);
    }
    std::string csv = "radius,power,anisotropy_db\n";
    for (size_t i = 0; i < radial.radius.size(); ++i)
      csv += fmt::format("{},{:.6g},{:.4g}\n", radial.radius[i], radial.power[i],
                         radial.anisotropy_db[i]);
    if (!o->csv.empty()) write_output(o->csv, csv, out);
    if (!o->svg.empty()) {
      LineSeries line{o->src.source,
                      {radial.radius.begin() + 1, radial.radius.end()},
                      {radial.power.begin() + 1, radial.power.end()}};
      write_output(
          o->svg,
          line_plot_svg({fmt::format("Radially averaged power, {} ({} points, {} realizations)",
                                     o->src.source, points, o->realizations),
                         "frequency |f|",
                         "power",
                         {},
                         0,
                         0,
                         true},
                        {line}),
          out);
    }
    if (o->json) {
      JsonObject doc = json_report("spectrum");
      doc.update(JsonObject{{"dimensions", 2},
                            {"source", o->src.source},
                            {"points", points},
                            {"seed", o->src.seed},
                            {"width", o->size},
                            {"height", o->size},
                            {"realizations", o->src.is_file() ? 1 : o->realizations}});
      JsonObject rows = JsonObject::array();
      for (size_t i = 0; i < radial.radius.size(); ++i)
        rows.push_back({{"radius", radial.radius[i]},
                        {"power", radial.power[i]},
                        {"anisotropy_db", radial.anisotropy_db[i]}});
      doc["rows"] = std::move(rows);
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "{}: {} points, {}x{} frequencies, {} realization(s); mean power {:.4f} "
        "past |f| = {}\n",
        o->src.source, points, o->size, o->size, o->realizations,
        [&] {
          double s = 0;
          int c = 0;
          for (size_t i = radial.radius.size() / 2; i < radial.radius.size(); ++i)
            s += radial.power[i], ++c;
          return c ? s / c : 0.0;
        }(),
        radial.radius.empty() ? 0.0 : radial.radius[radial.radius.size() / 2]);
  };
}

}  // namespace aapat
