// `aapat spectrum`: the Fourier power spectrum of a point set (2D, averaged
// over realizations or a file's sets), or Goss & Wu's 1D spectra (--1d).
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/text.h"
#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/io/png_image.h"
#include "aapat/study/point_set_study.h"
#include "cli/commands.h"
#include "cli/point_options.h"
#include "cli/progress.h"

namespace aapat {
namespace {

struct SpectrumOptions {
  PointOptions src;
  // The library's defaults; --n's is the 2D one (kDefaultSpectrumPoints)
  // and --1d's is kDefaultLinePoints unless --n is given.
  int size = SpectrumSettings{}.size, realizations = SpectrumSettings{}.realizations,
      frequencies = kDefaultLineFrequencies;
  double max_frequency = kDefaultLineMaxFrequency;
  const CLI::Option* n_option = nullptr;
  std::string png, csv, svg, one_d;
  bool json = false, fast = false;
};

// The options of --1d: the kinds, and the frequencies to evaluate.
void add_line_spectrum_options(CLI::App* cmd, SpectrumOptions& o) {
  cmd->add_option("--1d", o.one_d,
                  "Goss-Wu Fig. 8: 1D 'poisson' or 'jittered' with unit mean spacing");
  cmd->add_option("--frequencies", o.frequencies, "1D: frequencies evaluated")
      ->capture_default_str()
      ->check(CLI::Range(kMinLineFrequencies, kMaxLineFrequencies));
  cmd->add_option("--max-frequency", o.max_frequency,
                  "1D: highest frequency, cycles per mean spacing")
      ->capture_default_str()
      ->check(CLI::Range(kMinLineMaxFrequency, kMaxLineMaxFrequency));
}

std::string radial_svg(const SpectrumStudy& st, const std::string& source, int realizations) {
  const RadialProfile& radial = st.radial;
  LineSeries line{source,
                  {radial.radius.begin() + 1, radial.radius.end()},
                  {radial.power.begin() + 1, radial.power.end()}};
  return line_plot_svg({fmt::format("Radially averaged power, {} ({} points, {} realizations)",
                                    source, st.points, realizations),
                        "frequency |f|",
                        "power",
                        {},
                        0,
                        0,
                        true},
                       {line});
}

// --1d: one curve per kind in a comma list, in one table and one plot.
void run_line_spectra(const SpectrumOptions& o, std::ostream& out) {
  if (!o.png.empty())
    throw Error(
        "-o writes the 2D spectrum as a PNG; with --1d write --csv or --svg (a 1D spectrum "
        "is a curve)");
  if (!o.src.source.empty())
    throw Error(fmt::format("--1d draws its own 1D points; drop the source '{}'", o.src.source));
  std::vector<std::string> kinds;
  for (std::string_view k : split(o.one_d)) kinds.emplace_back(trim(k));
  const int n = o.n_option->count() ? o.src.n : kDefaultLinePoints;
  const auto spectra = line_spectra(kinds, n, o.src.seed, o.frequencies, o.max_frequency);
  const size_t count = spectra.back().points;
  const std::vector<double> frequency = line_frequencies(o.frequencies, o.max_frequency);
  if (!o.csv.empty()) {
    std::string csv = "frequency";
    for (const auto& kind : kinds) csv += "," + kind;
    csv += "\n";
    for (int k = 0; k < o.frequencies; ++k) {
      csv += fmt::format("{:.6g}", frequency[static_cast<size_t>(k)]);
      for (const auto& sp : spectra) csv += fmt::format(",{:.6g}", sp.power[k]);
      csv += "\n";
    }
    write_output(o.csv, csv, out);
  }
  if (o.json) {
    out << json_text(line_spectra_json(kinds, o.src.seed, o.frequencies, o.max_frequency, spectra));
  }
  if (!o.svg.empty()) {
    std::vector<LineSeries> lines;
    for (const auto& sp : spectra)
      lines.push_back(
          {fmt::format("{} ({} points)", sp.kind, sp.points), sp.bin_frequency, sp.bin_power});
    write_output(o.svg,
                 line_plot_svg({fmt::format("1D power spectra, {} points (Goss-Wu Fig. 8)", count),
                                "frequency (cycles per mean spacing)",
                                "power",
                                {},
                                0,
                                o.max_frequency,
                                true},
                               lines),
                 out);
  }
  if (!o.json)
    out << fmt::format("1D {}: {} points, {} frequencies up to {}\n", o.one_d, count, o.frequencies,
                       o.max_frequency);
}

}  // namespace

Action add_spectrum_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("spectrum", "Fourier power spectrum of a point set (2D, or 1D with --1d)");
  auto o = std::make_shared<SpectrumOptions>();
  cmd->add_option("source", o->src.source, "generator spec or a point file (2D; docs/formats.md)");
  o->src.n = kDefaultSpectrumPoints;
  o->src.add_common(cmd);
  o->n_option = cmd->get_option("--n");
  cmd->add_option("--size", o->size, "frequencies per axis, -size/2 .. size/2-1")
      ->capture_default_str()
      ->check(CLI::Range(kMinSpectrumSize, kMaxSpectrumSize));
  cmd->add_option("--realizations", o->realizations,
                  "point sets averaged (seeds seed, seed+1, ...)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxRealizations));
  cmd->add_option("-o,--output", o->png,
                  "the 2D spectrum as a PNG (grey = power / 2, DC at the centre)");
  cmd->add_option("--csv", o->csv, "radial average (2D) or the spectrum (1D) as CSV");
  cmd->add_option("--svg", o->svg, "radial average (2D) or the spectrum (1D) as an SVG plot");
  cmd->add_flag("--fast", o->fast,
                "a non-uniform FFT instead of the exact sum: any number of points, within the "
                "error bound it reports (even sizes)");
  add_line_spectrum_options(cmd, *o);
  cmd->add_flag("--json", o->json, "print the radial average (2D) or the spectrum (1D) as JSON");
  return [o](std::ostream& out) {
    if (!o->one_d.empty()) return run_line_spectra(*o, out);
    if (o->src.source.empty()) throw Error("spectrum: give a generator or a point file (or --1d)");
    if (!o->png.empty() && !o->png.ends_with(".png"))
      throw Error(fmt::format("--output: '{}' must end in .png", o->png));
    const PointOptions& src = o->src;
    // A file's sets are its realizations (UTK files hold several).
    const PointSets sets = src.is_file() ? src.file_sets() : PointSets{};
    SpectrumSettings s{o->size, src.is_file() ? static_cast<int>(sets.size()) : o->realizations,
                       src.is_file() ? 0 : static_cast<size_t>(src.n), o->fast};
    SpectrumStudy st;
    {
      Progress bar("spectrum");
      st = spectrum_study([&](int r) { return src.is_file() ? sets[r] : src.points(r); }, s,
                          bar.callback());
    }
    const RadialProfile& radial = st.radial;
    if (!o->png.empty()) write_png_gray(o->png, o->size, o->size, spectrum_grey_pixels(st.mean));
    std::string csv = "radius,power,anisotropy_db\n";
    for (size_t i = 0; i < radial.radius.size(); ++i)
      csv += fmt::format("{},{:.6g},{:.4g}\n", radial.radius[i], radial.power[i],
                         radial.anisotropy_db[i]);
    if (!o->csv.empty()) write_output(o->csv, csv, out);
    if (!o->svg.empty()) write_output(o->svg, radial_svg(st, src.source, s.realizations), out);
    if (o->json) {
      JsonObject doc = json_report("spectrum");
      doc.update(JsonObject{{"dimensions", 2},
                            {"source", src.source},
                            {"points", st.points},
                            {"seed", src.seed},
                            {"width", o->size},
                            {"height", o->size},
                            {"realizations", s.realizations},
                            {"method", o->fast ? "fast" : "exact"}});
      if (o->fast) doc["error_bound"] = st.error_bound;
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
        "{}: {} points, {}x{} frequencies, {} realization(s); mean power {:.4f} past |f| = {}\n",
        src.source, st.points, o->size, o->size, s.realizations, st.tail_power, st.tail_radius);
    if (o->fast)
      out << fmt::format(
          "fast spectrum (non-uniform FFT): |P - exact P| <= {:.2g} at every f != 0\n",
          st.error_bound);
  };
}

}  // namespace aapat
