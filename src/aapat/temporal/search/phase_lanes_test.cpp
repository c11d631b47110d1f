#include "aapat/temporal/search/phase_lanes.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <random>
#include <vector>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "testing/every_simd_path.h"

namespace aapat {
namespace {

// Random projections, some of them equal (ties take the sign 0 and form a
// group of the sorted path), and their filter values and sorted order.
struct Held {
  std::vector<double> p, moment, step;
  std::vector<size_t> order;
  HeldSamples at() const {
    return {p, moment, step,
            p.size() > kPairwiseLimit ? std::span<const size_t>(order) : std::span<const size_t>()};
  }
};
Held random_held(const Filter& filter, size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.7, 0.7);
  Held h;
  for (size_t j = 0; j < n; ++j) h.p.push_back(j > 0 && rng() % 5 == 0 ? h.p[rng() % j] : u(rng));
  h.moment.resize(n), h.step.resize(n);
  filter_values_at(filter, h.p, h.moment, h.step);
  sort_samples(h.p, h.order);
  return h;
}

// A phase array of random weights (negative ones too), zero past `phases`.
std::vector<double> random_phases(size_t n, size_t phases, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-0.3, 1);
  std::vector<double> w(n * phase_stride(phases), 0.0);
  for (size_t j = 0; j < n; ++j)
    for (size_t k = 0; k < phases; ++k) w[j * phase_stride(phases) + k] = u(rng);
  return w;
}

std::vector<double> column(const std::vector<double>& a, size_t n, size_t stride, size_t k) {
  std::vector<double> c(n);
  for (size_t j = 0; j < n; ++j) c[j] = a[j * stride + k];
  return c;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Every phase's E1^2, dp and dw are e1_squared_gradient's bits for that
// phase's weights, on every SIMD path, through the pair form (up to
// kPairwiseLimit samples) and the sorted one (past it).
RC_GTEST_PROP(PhaseLanes, E1SquaredIsTheOnePhaseGradientsBits, ()) {
  const char* filters[] = {"mitchell", "gaussian", "lanczos:lobes=2", "box", "tent"};
  const Filter filter = make_filter(filters[*rc::gen::inRange<size_t>(0, std::size(filters))]);
  const size_t n = *rc::gen::inRange<size_t>(1, 40), phases = *rc::gen::inRange<size_t>(1, 21);
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  const Held h = random_held(filter, n, rng);
  const std::vector<double> w = random_phases(n, phases, rng);
  const size_t stride = phase_stride(phases);
  // The rows' share: coef 0 for some phases (they add nothing).
  std::vector<double> coef(stride, 0.0);
  for (size_t k = 0; k < phases; ++k) coef[k] = k % 3 == 2 ? 0.0 : 0.25 + 0.125 * k;
  const double scale = 0.75, nx = -0.6, ny = 0.8;
  testing::EveryPath paths;
  paths.run([&] {
    std::vector<double> e1(stride), dw(n * stride), gx(n * stride, 0.5), gy(n * stride, -0.5),
        gx_only(n * stride, 0.5), gy_only(n * stride, -0.5);
    e1_squared_phases(filter.half_mean_distance(), h.at(), w.data(), stride, phases, e1.data());
    e1_squared_derivatives_phases(h.at(), w.data(), stride, phases,
                                  {coef.data(), scale, nx, ny, gx.data(), gy.data()}, dw.data());
    e1_squared_derivatives_phases(h.at(), w.data(), stride, phases,
                                  {coef.data(), scale, nx, ny, gx_only.data(), gy_only.data()},
                                  nullptr);
    for (size_t k = 0; k < phases; ++k) {
      std::vector<double> dpk(n), dwk(n);
      const double e = e1_squared_gradient(filter.half_mean_distance(), h.at(),
                                           column(w, n, stride, k), dpk, dwk);
      RC_ASSERT(same_bits(e1[k], e));
      for (size_t j = 0; j < n; ++j) {
        const size_t at = j * stride + k;
        const double term = coef[k] == 0 ? 0.0 : coef[k] * (scale * dpk[j]);
        RC_ASSERT(same_bits(gx[at], 0.5 + term * nx));
        RC_ASSERT(same_bits(gy[at], -0.5 + term * ny));
        RC_ASSERT(same_bits(gx_only[at], gx[at]));
        RC_ASSERT(same_bits(dw[at], dwk[j]));
      }
    }
  });
}

// The flicker's F = sum_j |R_j| (p_(j+1) - p_(j)) by its definition, and its
// derivatives by central differences (positions apart, so that no small
// step reorders them).
RC_GTEST_PROP(PhaseLanes, FlickerIsItsDefinitionWithItsDerivatives, ()) {
  const size_t n = *rc::gen::inRange<size_t>(1, 30), phases = *rc::gen::inRange<size_t>(1, 21);
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  std::vector<double> p;
  for (size_t j = 0; j < n; ++j) p.push_back(0.05 * static_cast<double>(j) + 0.01 * (rng() % 3));
  std::shuffle(p.begin(), p.end(), rng);
  std::vector<size_t> order;
  sort_samples(p, order);
  const std::vector<double> c = random_phases(n, phases, rng);
  const size_t stride = phase_stride(phases);
  const auto flicker = [&](const std::vector<double>& at, const std::vector<double>& ck) {
    std::vector<size_t> o;
    sort_samples(at, o);
    double running = 0, f = 0;
    for (size_t j = 0; j + 1 < n; ++j) {
      running += ck[o[j]];
      f += std::abs(running) * (at[o[j + 1]] - at[o[j]]);
    }
    return f * f;
  };
  std::vector<double> first;
  testing::EveryPath paths;
  paths.run([&] {
    // dF^2/dp through a row that adds it as it is: 0 + (1 (1 d)) 1.
    std::vector<double> f2(stride), dp(n * stride, 0.0), unused(n * stride, 0.0), dc(n * stride),
        ones(stride, 1.0);
    flicker_squared_phases(p, order, c.data(), stride, phases, f2.data());
    flicker_squared_derivatives_phases(p, order, c.data(), stride, phases,
                                       {ones.data(), 1.0, 1.0, 0.0, dp.data(), unused.data()},
                                       dc.data());
    std::vector<double> all = f2;
    all.insert(all.end(), dp.begin(), dp.end());
    all.insert(all.end(), dc.begin(), dc.end());
    if (first.empty()) first = all;
    for (size_t i = 0; i < all.size(); ++i) RC_ASSERT(same_bits(all[i], first[i]));
    const double h = 1e-6;
    for (size_t k = 0; k < phases; ++k) {
      std::vector<double> ck = column(c, n, stride, k);
      const double f = flicker(p, ck);
      RC_ASSERT(std::abs(f2[k] - f) <= 1e-12 * (1 + f));
      for (size_t j = 0; j < n; ++j) {
        std::vector<double> up = p, down = p;
        up[j] += h, down[j] -= h;
        const double by_p = (flicker(up, ck) - flicker(down, ck)) / (2 * h);
        RC_ASSERT(std::abs(dp[j * stride + k] - by_p) <= 1e-5 * (1 + std::abs(by_p)));
        std::vector<double> c_up = ck, c_down = ck;
        c_up[j] += h, c_down[j] -= h;
        const double by_c = (flicker(p, c_up) - flicker(p, c_down)) / (2 * h);
        RC_ASSERT(std::abs(dc[j * stride + k] - by_c) <= 1e-5 * (1 + std::abs(by_c)));
      }
    }
  });
}

// The upscale search's terms: for every phase, the bits of the one-phase
// loops they replace (e1_squared_in_order of the phase's weights, and the
// flicker sweep of its changes) on every SIMD path, with equal projections,
// negative weights and any count of frames and phases.
RC_GTEST_PROP(PhaseLanes, SortedTermsAreTheOnePhaseLoopsBits, ()) {
  const char* filters[] = {"mitchell", "gaussian", "lanczos:lobes=2", "box"};
  const Filter filter = make_filter(filters[*rc::gen::inRange<size_t>(0, std::size(filters))]);
  const size_t n = *rc::gen::inRange<size_t>(0, 60), phases = *rc::gen::inRange<size_t>(1, 26);
  const size_t frames = *rc::gen::inRange<size_t>(1, 8), stride = phase_stride(phases);
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  std::uniform_real_distribution<double> pos(-1.2, 1.2), weight(-0.2, 1);
  std::vector<double> p(n), w(n), j(n);
  std::vector<size_t> frame(n);
  for (size_t i = 0; i < n; ++i) {
    p[i] = i > 0 && rng() % 4 == 0 ? p[rng() % i] : pos(rng);
    w[i] = weight(rng);
    frame[i] = rng() % frames;
  }
  std::sort(p.begin(), p.end());
  for (size_t i = 0; i < n; ++i) j[i] = filter.abs_moment(p[i]);
  std::vector<size_t> in_order(n);
  std::iota(in_order.begin(), in_order.end(), size_t{0});
  // Phase arrays over frames, zero past the phases.
  std::vector<double> u(frames * stride, 0.0), c(frames * stride, 0.0);
  for (size_t f = 0; f < frames; ++f)
    for (size_t k = 0; k < phases; ++k) {
      u[f * stride + k] = weight(rng);
      c[f * stride + k] = weight(rng) - weight(rng);
    }
  std::vector<double> e1_expected(phases), f_expected(phases);
  for (size_t k = 0; k < phases; ++k) {
    std::vector<double> wk(n);
    for (size_t i = 0; i < n; ++i) wk[i] = u[frame[i] * stride + k] * w[i];
    e1_expected[k] = e1_squared_in_order(filter, p, wk, in_order);
    double running = 0, integral = 0;
    for (size_t i = 0; i + 1 < n; ++i) {
      running += c[frame[i] * stride + k] * w[i];
      integral += std::abs(running) * (p[i + 1] - p[i]);
    }
    f_expected[k] = integral;
  }
  testing::EveryPath paths;
  paths.run([&] {
    std::vector<double> e1(stride), f(stride);
    sorted_terms_phases(filter.half_mean_distance(), {p, j, w, frame}, u.data(), c.data(), stride,
                        phases, e1.data(), f.data());
    for (size_t k = 0; k < phases; ++k) {
      RC_ASSERT(same_bits(e1[k], e1_expected[k]));
      RC_ASSERT(same_bits(f[k], f_expected[k]));
    }
  });
}

}  // namespace
}  // namespace aapat
