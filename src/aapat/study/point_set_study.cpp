#include "aapat/study/point_set_study.h"

#include "aapat/core/point_checks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/text.h"
#include "aapat/generate/point_processes.h"

namespace aapat {
namespace {

void check_spectrum_work(size_t points, int size, int realizations) {
  const double work = static_cast<double>(points) * size * size * realizations;
  if (work > kMaxSpectrumTerms)
    throw Error(fmt::format(
        "spectrum: {} points x {}^2 frequencies x {} realizations = {:.3g} terms exceed the "
        "limit of {:.3g}; use fewer points, frequencies or realizations",
        points, size, realizations, work, kMaxSpectrumTerms));
}

}  // namespace

DiscrepancyMeasures parse_measures(std::string_view list) {
  std::string names;
  for (const L2KindInfo& k : l2_kinds()) names += std::string(k.name) + ", ";
  names += "star, edge or all";
  DiscrepancyMeasures m{{}, false, false};
  std::vector<bool> l2(l2_kinds().size(), false);
  for (std::string_view item : split(list)) {
    item = trim(item);
    if (item == "l2-centered") item = "l2-centred";
    bool known = item == "star" || item == "edge" || item == "all";
    m.star = m.star || item == "star" || item == "all";
    m.edge = m.edge || item == "edge" || item == "all";
    for (size_t k = 0; k < l2.size(); ++k)
      if (item == l2_kinds()[k].name || item == "all") l2[k] = known = true;
    if (!known)
      throw ParameterError("measure", fmt::format(" '{}': the measures are {}", item, names));
  }
  for (size_t k = 0; k < l2.size(); ++k)
    if (l2[k]) m.l2.push_back(l2_kinds()[k].kind);
  if (m.l2.empty() && !m.star && !m.edge)
    throw ParameterError("measure", fmt::format(": name at least one of {}", names));
  return m;
}

DiscrepancyReport discrepancy_report(const std::vector<Vec2>& points,
                                     const DiscrepancyMeasures& measures,
                                     const StudyProgress& progress) {
  // Every check first, before any work.
  check_unit_square(points, "points");
  if (!measures.l2.empty()) check_l2_star_size(points.size());
  if (measures.star || measures.edge) check_discrepancy_size(points.size());
  const int total = static_cast<int>(measures.l2.size()) + measures.star + measures.edge;
  int done = 0;
  auto report = [&](const std::string& note) {
    if (progress) progress(done, total, note);
  };
  DiscrepancyReport r;
  r.points = points.size();
  for (const L2Kind kind : measures.l2) {
    report(std::string(l2_kind_info(kind).label));
    r.l2.push_back({kind, l2_discrepancy(points, kind)});
    ++done;
  }
  if (measures.star) {
    report("star");
    r.star = star_discrepancy(points);
    ++done;
  }
  if (measures.edge) {
    report("edge");
    r.edge = edge_discrepancy(points, 720, [&](int finished, int directions) {
      if (finished % 16 == 0) report(fmt::format("edge {}/{}", finished, directions));
    });
  }
  return r;
}

SpectrumStudy spectrum_study(const PointSource& source, const SpectrumSettings& s,
                             const StudyProgress& progress) {
  if (!(s.size >= kMinSpectrumSize && s.size <= kMaxSpectrumSize))
    throw ParameterError("size", fmt::format(" {}: expected {} to {} frequencies", s.size,
                                             kMinSpectrumSize, kMaxSpectrumSize));
  if (!(s.realizations >= 1 && s.realizations <= 100000))
    throw ParameterError("realizations", fmt::format(" {}: expected 1 to 100000", s.realizations));
  if (s.fast && s.size % 2 != 0)
    throw ParameterError("size", fmt::format(" {}: the fast spectrum takes an even size", s.size));
  if (s.expected_points > 0 && !s.fast)
    check_spectrum_work(s.expected_points, s.size, s.realizations);
  SpectrumStudy out;
  for (int r = 0; r < s.realizations; ++r) {
    const auto pts = source(r);
    check_unit_square(pts, "points");
    out.points = pts.size();
    if (s.fast) {
      // The mean's error is at most the largest realization's bound.
      const FastSpectrum f = power_spectrum_fast(pts, s.size);
      accumulate(out.mean, f.spectrum, 1.0 / s.realizations);
      out.error_bound = std::max(out.error_bound, f.error_bound);
    } else {
      check_spectrum_work(out.points, s.size, 1);
      accumulate(out.mean, power_spectrum(pts, s.size), 1.0 / s.realizations);
    }
    if (progress) progress(r + 1, s.realizations, "");
  }
  out.radial = radial_average(out.mean);
  const auto& radius = out.radial.radius;
  if (!radius.empty()) {
    double sum = 0;
    int count = 0;
    for (size_t i = radius.size() / 2; i < radius.size(); ++i) sum += out.radial.power[i], ++count;
    out.tail_power = sum / count;
    out.tail_radius = radius[radius.size() / 2];
  }
  return out;
}

std::vector<double> line_frequencies(int frequencies, double max_frequency) {
  std::vector<double> f(static_cast<size_t>(std::max(frequencies, 0)));
  for (int k = 0; k < frequencies; ++k) f[static_cast<size_t>(k)] = k * max_frequency / frequencies;
  return f;
}

std::vector<LineSpectrum> line_spectra(const std::vector<std::string>& kinds, int n, uint64_t seed,
                                       int frequencies, double max_frequency) {
  if (frequencies < kMinLineFrequencies || frequencies > kMaxLineFrequencies)
    throw Error(fmt::format("frequencies {} is not in [{}, {}]", frequencies, kMinLineFrequencies,
                            kMaxLineFrequencies));
  if (!(max_frequency >= kMinLineMaxFrequency && max_frequency <= kMaxLineMaxFrequency))
    throw Error(fmt::format("max_frequency {} is not in [{}, {}] cycles per mean spacing",
                            max_frequency, kMinLineMaxFrequency, kMaxLineMaxFrequency));
  std::vector<LineSpectrum> out;
  for (const auto& kind : kinds) {
    const auto xs = line_points(kind, n, seed);
    LineSpectrum line{kind, xs.size(), power_spectrum_1d(xs, frequencies, max_frequency), {}, {}};
    const int bins = std::min(frequencies, 2000);
    const int first = static_cast<int>(std::ceil(2.0 / xs.size() / max_frequency * frequencies));
    for (int b = 0; b < bins; ++b) {
      const int k0 = std::max(first, b * frequencies / bins), k1 = (b + 1) * frequencies / bins;
      if (k1 <= k0) continue;
      double sum = 0;
      for (int k = k0; k < k1; ++k) sum += line.power[k];
      line.bin_frequency.push_back((k0 + k1) / 2.0 * max_frequency / frequencies);
      line.bin_power.push_back(sum / std::max(1, k1 - k0));
    }
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace aapat
