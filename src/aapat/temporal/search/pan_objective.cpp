#include "aapat/temporal/search/pan_objective.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <tbb/parallel_for.h>

#include "aapat/temporal/sequence/render_scale.h"

namespace aapat {

struct PanObjective::State {
  // One frame's reconstruction along one axis: for each display coordinate
  // from `lo`, the render columns (or rows) within the filter's radius and
  // their weights h, divided by the axis' sum (the 2D weights h(dx) h(dy)
  // over their sum are the products of the two axes').
  struct AxisWeights {
    int lo = 0, stride = 0;
    std::vector<int> index;
    std::vector<double> weight;
    std::vector<int> count;
  };

  static AxisWeights axis_weights(double jitter, int lo, int hi, double ratio, const Filter& h,
                                  double* smallest_sum) {
    AxisWeights out;
    out.lo = lo;
    out.stride = 2 * static_cast<int>(std::ceil(h.radius())) + 4;
    const auto n = static_cast<size_t>(hi - lo + 1);
    out.index.assign(n * static_cast<size_t>(out.stride), 0);
    out.weight.assign(n * static_cast<size_t>(out.stride), 0.0);
    out.count.assign(n, 0);
    for (int x = lo; x <= hi; ++x) {
      const size_t at = static_cast<size_t>(x - lo);
      const double u = to_render(x, ratio);
      double sum = 0;
      int used = 0;
      for (auto a = static_cast<int>(std::floor(u - h.radius() - 1));
           a <= static_cast<int>(std::ceil(u + h.radius() + 1)); ++a) {
        const double r = a + jitter - u;
        if (std::abs(r) > h.radius()) continue;
        const double w = h.value(r);
        if (w == 0) continue;
        const size_t slot = at * static_cast<size_t>(out.stride) + static_cast<size_t>(used++);
        out.index[slot] = a;
        out.weight[slot] = w;
        sum += w;
      }
      out.count[at] = used;
      *smallest_sum = std::min(*smallest_sum, std::abs(sum));
      for (int i = 0; i < used; ++i) out.weight[at * static_cast<size_t>(out.stride) + i] /= sum;
    }
    return out;
  }

  int period = 0;
  std::vector<PanCase> cases;
  Metric metric;
  double ratio = 1;
  std::vector<int> pixels;
  int coord_lo = 0, coord_hi = 0;  // the display coordinates a chain reaches
  std::vector<Vec2> jitter;
  std::vector<AxisWeights> x_weights, y_weights;  // per frame

  struct Case {
    std::vector<double> ages;
    std::vector<std::vector<PanChainEntry>> chains;
    std::vector<std::array<int, 4>> reach;  // per age: the chain's dx, dy from and to
    std::vector<long> first;                // per angle: the first bin's index on the kPanBin grid
    std::vector<size_t> begin;              // per angle: where its bins start within a kernel
    size_t bins = 0;                        // per kernel, over every angle
    double total = 0;                       // every kernel's weight (jitter-free)
    std::vector<double> bins_of;            // kernels x bins x (w, w p), a bin's pair together
    std::vector<double> e2;                 // per kernel
  };
  std::vector<Case> data;
  size_t kernels_per_case = 0;

  explicit State(const Metric& m) : metric(m) {}

  // Adds (sign +1) or takes out (-1) age d of kernel `kernel` of case c,
  // showing a frame of jitter j with the given axis weights. Every chain
  // offset's reconstruction is summed onto the render samples it reads
  // (many offsets read the same one), and each render sample, now at
  // R (its render position) + d v from the pixel, is binned once per angle.
  void bin_age(const Case& c, const PanModel& m, size_t kernel, size_t d, Vec2 j,
               const AxisWeights& xs, const AxisWeights& ys, double sign, double* bins) const {
    const size_t per_pixel_row = pixels.size() * static_cast<size_t>(period);
    const int px = pixels[kernel / per_pixel_row];
    const int py = pixels[(kernel / static_cast<size_t>(period)) % pixels.size()];
    const auto [dx0, dx1, dy0, dy1] = c.reach[d];
    const double radius = m.upscale.reconstruction.radius();
    const auto a0 = static_cast<int>(std::floor(to_render(px + dx0, ratio) - radius - 1)),
               a1 = static_cast<int>(std::ceil(to_render(px + dx1, ratio) + radius + 1)),
               b0 = static_cast<int>(std::floor(to_render(py + dy0, ratio) - radius - 1)),
               b1 = static_cast<int>(std::ceil(to_render(py + dy1, ratio) + radius + 1));
    const auto na = static_cast<size_t>(a1 - a0 + 1), nb = static_cast<size_t>(b1 - b0 + 1);
    thread_local std::vector<double> grid;
    grid.assign(na * nb, 0.0);
    for (const PanChainEntry& e : c.chains[d]) {
      const size_t xi = static_cast<size_t>(px + e.dx - xs.lo),
                   yi = static_cast<size_t>(py + e.dy - ys.lo);
      const int* ia = &xs.index[xi * static_cast<size_t>(xs.stride)];
      const double* wa = &xs.weight[xi * static_cast<size_t>(xs.stride)];
      const int* ib = &ys.index[yi * static_cast<size_t>(ys.stride)];
      const double* wb = &ys.weight[yi * static_cast<size_t>(ys.stride)];
      for (int b = 0; b < ys.count[yi]; ++b) {
        double* row = &grid[static_cast<size_t>(ib[b] - b0) * na];
        const double wy = e.c * wb[b];
        for (int a = 0; a < xs.count[xi]; ++a) row[ia[a] - a0] += wy * wa[a];
      }
    }
    // The render samples read, each where it is now relative to the pixel's
    // centre, and its weight.
    thread_local std::vector<double> sx, sy, sw;
    sx.clear(), sy.clear(), sw.clear();
    const double scale = sign * c.ages[d] / c.total;
    for (size_t b = 0; b < nb; ++b)
      for (size_t a = 0; a < na; ++a) {
        const double g = grid[b * na + a];
        if (g == 0) continue;
        sx.push_back(ratio * (a0 + static_cast<int>(a) + j.x) - px + (ratio - 1) / 2 +
                     static_cast<double>(d) * m.velocity.x);
        sy.push_back(ratio * (b0 + static_cast<int>(b) + j.y) - py + (ratio - 1) / 2 +
                     static_cast<double>(d) * m.velocity.y);
        sw.push_back(scale * g);
      }
    const auto angles = static_cast<size_t>(metric.angle_count());
    for (size_t an = 0; an < angles; ++an) {
      const double cs = metric.cos(static_cast<int>(an)), sn = metric.sin(static_cast<int>(an));
      const long first = c.first[an];
      const long last =
          static_cast<long>((an + 1 < angles ? c.begin[an + 1] : c.bins) - c.begin[an]) - 1;
      double* angle_bins = bins + 2 * c.begin[an];
      for (size_t i = 0; i < sw.size(); ++i) {
        const double p = cs * sy[i] - sn * sx[i];
        const auto at = static_cast<size_t>(std::clamp(pan_bin(p) - first, 0L, last));
        angle_bins[2 * at] += sw[i];
        angle_bins[2 * at + 1] += sw[i] * p;
      }
    }
  }

  // The kernel's E2 from its bins, as evaluate_pan reads its binned kernels.
  double kernel_e2(const Case& c, const double* bins) const {
    thread_local std::vector<double> weights, positions, values;
    const auto angles = static_cast<size_t>(metric.angle_count());
    values.resize(angles);
    for (size_t a = 0; a < angles; ++a) {
      const size_t begin = c.begin[a], end = a + 1 < angles ? c.begin[a + 1] : c.bins;
      weights.resize(end - begin);
      positions.resize(end - begin);
      for (size_t i = begin; i < end; ++i) {
        const double edge =
            static_cast<double>(c.first[a] + static_cast<long>(i - begin)) * kPanBin;
        const double w = bins[2 * i], wp = bins[2 * i + 1];
        weights[i - begin] = w;
        positions[i - begin] =
            std::abs(w) > 1e-12 ? std::clamp(wp / w, edge, edge + kPanBin) : edge + kPanBin / 2;
      }
      values[a] = metric.weight_sq(static_cast<int>(a)) *
                  binned_e1_squared(weights, positions, metric.filter());
    }
    return combine_over_angles(values, metric.norm());
  }

  AxisWeights weights_of(double jitter_axis) const {
    double smallest = HUGE_VAL;
    AxisWeights out = axis_weights(jitter_axis, coord_lo, coord_hi, ratio,
                                   cases[0].model.upscale.reconstruction, &smallest);
    if (!(smallest * smallest > 1e-9))  // where the engine falls back to one sample
      throw Error(fmt::format("the reconstruction filter {} gives a jitter of {} no weight",
                              cases[0].model.upscale.reconstruction.name(), jitter_axis));
    return out;
  }
};

PanObjective::PanObjective(int period, std::vector<PanCase> cases, const Metric& metric)
    : state_(std::make_unique<State>(metric)) {
  State& s = *state_;
  if (period < 1 || period > kMaxPanFrames)
    throw ParameterError(
        "frames", fmt::format(" {}: a pan's evaluation takes 1 to {}", period, kMaxPanFrames));
  if (cases.empty()) throw ParameterError("velocity", ": give at least one");
  for (const PanCase& c : cases)
    if (c.model.upscale.ratio != cases[0].model.upscale.ratio ||
        c.model.upscale.reconstruction.name() != cases[0].model.upscale.reconstruction.name())
      throw Error("the pan objective's cases must share the ratio and the reconstruction filter");
  s.period = period;
  s.cases = std::move(cases);
  s.ratio = s.cases[0].model.upscale.ratio;
  check_ratio(s.ratio);
  s.pixels = upscale_phase_pixels(s.ratio);
  s.kernels_per_case = s.pixels.size() * s.pixels.size() * static_cast<size_t>(period);
  const auto angles = static_cast<size_t>(metric.angle_count());
  const double radius = s.cases[0].model.upscale.reconstruction.radius();
  int reach_lo = 0, reach_hi = 0;
  size_t bytes = 0;
  for (const PanCase& pc : s.cases) {
    State::Case& c = s.data.emplace_back();
    PanModel m = pc.model;
    m.chain_cut = std::max(m.chain_cut, kPanEvaluationChainCut);
    c.ages = ema_age_weights(pc.alpha, period, kPanAgeCut);
    c.chains = pan_chains(m, c.ages.size());
    std::vector<double> lo(angles, HUGE_VAL), hi(angles, -HUGE_VAL);
    for (size_t d = 0; d < c.chains.size(); ++d) {
      double chain_sum = 0;
      std::array<int, 4> reach{0, 0, 0, 0};
      for (const PanChainEntry& e : c.chains[d]) {
        reach = {std::min(reach[0], e.dx), std::max(reach[1], e.dx), std::min(reach[2], e.dy),
                 std::max(reach[3], e.dy)};
        reach_lo = std::min({reach_lo, e.dx, e.dy});
        reach_hi = std::max({reach_hi, e.dx, e.dy});
        chain_sum += e.c;
        const double sx = e.dx + static_cast<double>(d) * m.velocity.x,
                     sy = e.dy + static_cast<double>(d) * m.velocity.y;
        for (size_t a = 0; a < angles; ++a) {
          const double p =
              metric.cos(static_cast<int>(a)) * sy - metric.sin(static_cast<int>(a)) * sx;
          lo[a] = std::min(lo[a], p);
          hi[a] = std::max(hi[a], p);
        }
      }
      c.reach.push_back(reach);
      c.total += c.ages[d] * chain_sum;
    }
    for (size_t a = 0; a < angles; ++a) {
      // A sample lies within the radius (render pixels) of its row and
      // column's centre, whose display pixel the chain reaches.
      const double margin = s.ratio * (radius + 1) *
                                (std::abs(metric.cos(static_cast<int>(a))) +
                                 std::abs(metric.sin(static_cast<int>(a)))) +
                            kPanBin;
      const auto first = static_cast<long>(std::floor((lo[a] - margin) / kPanBin));
      const auto last = static_cast<long>(std::floor((hi[a] + margin) / kPanBin));
      c.first.push_back(first);
      c.begin.push_back(c.bins);
      c.bins += static_cast<size_t>(last - first + 1);
    }
    bytes += 2 * sizeof(double) * c.bins * s.kernels_per_case;
  }
  if (bytes > kMaxPanObjectiveBytes)
    throw Error(fmt::format(
        "the pan search's bins would take {:.1f} GiB (at most {:.0f} GiB): give fewer "
        "--velocity, a coarser --acuity (uniform:step=4 takes a quarter of uniform:step=1's) "
        "or a shorter sequence",
        static_cast<double>(bytes) / (1 << 30),
        static_cast<double>(kMaxPanObjectiveBytes) / (1 << 30)));
  for (State::Case& c : s.data) {
    c.bins_of.assign(2 * c.bins * s.kernels_per_case, 0.0);
    c.e2.assign(s.kernels_per_case, 0.0);
  }
  const auto [pmin, pmax] = std::minmax_element(s.pixels.begin(), s.pixels.end());
  s.coord_lo = *pmin + reach_lo;
  s.coord_hi = *pmax + reach_hi;
}

PanObjective::~PanObjective() = default;

void PanObjective::set(const std::vector<Vec2>& jitter) {
  State& s = *state_;
  if (static_cast<int>(jitter.size()) != s.period)
    throw Error(fmt::format("the pan objective holds {} frames, not {}", s.period, jitter.size()));
  std::vector<State::AxisWeights> xs, ys;
  for (const Vec2 j : jitter) {
    xs.push_back(s.weights_of(j.x));
    ys.push_back(s.weights_of(j.y));
  }
  s.jitter = jitter;
  s.x_weights = std::move(xs);
  s.y_weights = std::move(ys);
  tbb::parallel_for(size_t{0}, s.data.size() * s.kernels_per_case, [&](size_t at) {
    State::Case& c = s.data[at / s.kernels_per_case];
    const size_t kernel = at % s.kernels_per_case;
    double* bins = c.bins_of.data() + 2 * kernel * c.bins;
    std::fill_n(bins, 2 * c.bins, 0.0);
    const int k = static_cast<int>(kernel % static_cast<size_t>(s.period));
    for (size_t d = 0; d < c.ages.size(); ++d) {
      const auto f =
          static_cast<size_t>(((k - static_cast<int>(d)) % s.period + s.period) % s.period);
      s.bin_age(c, s.cases[at / s.kernels_per_case].model, kernel, d, s.jitter[f], s.x_weights[f],
                s.y_weights[f], 1, bins);
    }
    c.e2[kernel] = s.kernel_e2(c, bins);
  });
}

void PanObjective::move(int frame, Vec2 j) {
  update(frame, j, true);
}

double PanObjective::try_move(int frame, Vec2 j) {
  return update(frame, j, false);
}

double PanObjective::update(int frame, Vec2 j, bool keep) {
  State& s = *state_;
  if (s.jitter.empty()) throw Error("the pan objective has no jitter yet: set() first");
  if (frame < 0 || frame >= s.period)
    throw Error(fmt::format("frame {} of a {}-frame pan objective", frame, s.period));
  const auto f = static_cast<size_t>(frame);
  State::AxisWeights xs = s.weights_of(j.x), ys = s.weights_of(j.y);
  // A try rebins a copy of each kernel's bins and keeps only its E2.
  std::vector<std::vector<double>> tried(s.data.size());
  if (!keep)
    for (size_t i = 0; i < s.data.size(); ++i) tried[i] = s.data[i].e2;
  tbb::parallel_for(size_t{0}, s.data.size() * s.kernels_per_case, [&](size_t at) {
    State::Case& c = s.data[at / s.kernels_per_case];
    const PanModel& m = s.cases[at / s.kernels_per_case].model;
    const size_t kernel = at % s.kernels_per_case;
    const int k = static_cast<int>(kernel % static_cast<size_t>(s.period));
    thread_local std::vector<double> copy;
    double* bins = c.bins_of.data() + 2 * kernel * c.bins;
    bool copied = false, touched = false;
    // Ages d showing frame f: d = k - f modulo the period.
    for (auto d = static_cast<size_t>(((k - frame) % s.period + s.period) % s.period);
         d < c.ages.size(); d += static_cast<size_t>(s.period)) {
      if (!keep && !copied) {
        copy.assign(bins, bins + 2 * c.bins);
        bins = copy.data();
        copied = true;
      }
      s.bin_age(c, m, kernel, d, s.jitter[f], s.x_weights[f], s.y_weights[f], -1, bins);
      s.bin_age(c, m, kernel, d, j, xs, ys, 1, bins);
      touched = true;
    }
    if (touched) (keep ? c.e2 : tried[at / s.kernels_per_case])[kernel] = s.kernel_e2(c, bins);
  });
  if (!keep) return mean_of(tried);
  s.jitter[f] = j;
  s.x_weights[f] = std::move(xs);
  s.y_weights[f] = std::move(ys);
  return value();
}

namespace {

// Each case's mean over its kernels, summed in a fixed order (the same at
// any thread count).
std::vector<double> case_means(const std::vector<std::vector<double>>& e2) {
  std::vector<double> out;
  for (const std::vector<double>& kernels : e2) {
    double sum = 0;
    for (const double e : kernels) sum += e;
    out.push_back(sum / static_cast<double>(kernels.size()));
  }
  return out;
}

}  // namespace

double PanObjective::mean_of(const std::vector<std::vector<double>>& e2) {
  const std::vector<double> v = case_means(e2);
  double sum = 0;
  for (const double e : v) sum += e;
  return sum / static_cast<double>(v.size());
}

std::vector<double> PanObjective::case_values() const {
  std::vector<std::vector<double>> e2;
  for (const State::Case& c : state_->data) e2.push_back(c.e2);
  return case_means(e2);
}

double PanObjective::value() const {
  std::vector<std::vector<double>> e2;
  for (const State::Case& c : state_->data) e2.push_back(c.e2);
  return mean_of(e2);
}

const std::vector<Vec2>& PanObjective::jitter() const {
  return state_->jitter;
}

size_t PanObjective::bytes() const {
  size_t out = 0;
  for (const State::Case& c : state_->data) out += c.bins_of.size() * sizeof(double);
  return out;
}

}  // namespace aapat
