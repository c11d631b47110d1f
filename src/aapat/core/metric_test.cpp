#include "aapat/core/metric.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric_simd.h"
#include "testing/quadrature.h"

namespace aapat {
namespace {

const std::vector<std::string>& filter_specs() {
  static const std::vector<std::string> specs = [] {
    std::vector<std::string> v;
    for (const auto& f : filter_registry().entries()) v.push_back(f.info.name);
    return v;
  }();
  return specs;
}

double e1_1d(const Filter& f, std::vector<double> p, std::vector<double> w) {
  return std::sqrt(e1_squared(f, p, w));
}

// E1 of one centred sample against the filter's own integral:
// E1^2 = 2 int_0^R (1 - g0(a))^2 da, integrated independently from h.
TEST(E1ClosedForm, SingleCentredSampleEveryFilter) {
  for (const auto& spec : filter_specs()) {
    const Filter f = make_filter(spec);
    const double r = f.radius();
    const double numeric = 2 * testing::integrate_pieces(
                                   [&](double a) {
                                     const double g = testing::integrate_pieces(
                                         [&](double x) { return f.value(x); }, -r, a, r / 4);
                                     return (1 - g) * (1 - g);
                                   },
                                   0, r, r / 4);
    EXPECT_NEAR(e1_squared(f, std::vector<double>{0.0}, std::vector<double>{1.0}), numeric, 1e-9)
        << spec;
  }
}

// Box of width 1: E1^2(p) = ((p + 1/2)^3 + (1/2 - p)^3) / 3 for one sample at p.
TEST(E1ClosedForm, SingleSampleBox) {
  const Filter box = make_filter("box");
  for (double p : {-0.5, -0.3, 0.0, 0.1, 0.4}) {
    const double expected = (std::pow(p + 0.5, 3) + std::pow(0.5 - p, 3)) / 3;
    EXPECT_NEAR(e1_squared(box, std::vector<double>{p}, std::vector<double>{1.0}), expected, 1e-15);
  }
  EXPECT_NEAR(e1_1d(box, {0.0}, {1.0}), std::sqrt(1.0 / 12), 1e-15);
  // Tent: E1^2 = 2 int_0^1 ((1 - a)^2 / 2)^2 = 1/10.
  EXPECT_NEAR(e1_squared(make_filter("tent"), std::vector<double>{0.0}, std::vector<double>{1.0}),
              0.1, 1e-15);
}

// N equal samples at the centres of N equal cells against the box: each cell
// contributes a sawtooth, E1 = 1 / (N sqrt(12)).
TEST(E1ClosedForm, UniformGridAgainstBox) {
  const Filter box = make_filter("box");
  for (int n : {1, 2, 3, 5, 8, 40}) {
    std::vector<double> p, w(n, 1.0 / n);
    for (int i = 0; i < n; ++i) p.push_back((i + 0.5) / n - 0.5);
    EXPECT_NEAR(e1_1d(box, p, w), 1 / (n * std::sqrt(12.0)), 1e-13) << n;
  }
}

// The closed form (energy identity) agrees with integrating piece by piece,
// for every filter, signed weights, samples inside and outside the support,
// and kernels on both sides of the pairwise/sorted switch.
RC_GTEST_PROP(E1ClosedForm, AgreesWithPiecewiseIntegration, ()) {
  const auto& specs = filter_specs();
  const Filter f = make_filter(specs[*rc::gen::inRange<size_t>(0, specs.size())]);
  const int n = *rc::gen::inRange(1, 41);
  const bool signed_weights = *rc::gen::arbitrary<bool>();
  std::vector<double> p(n), w(n);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    p[i] = *rc::gen::inRange(-3000, 3001) / 1000.0;
    w[i] = *rc::gen::inRange(signed_weights ? -500 : 1, 1001) / 1000.0;
    sum += w[i];
  }
  RC_PRE(std::abs(sum) > 0.05);
  for (double& v : w) v /= sum;
  const double closed = e1_squared(f, p, w);
  const double piecewise = e1_squared_piecewise(f, p, w);
  RC_ASSERT(std::abs(closed - piecewise) <= 1e-10 * std::max(1.0, std::abs(piecewise)));
}

Kernel random_kernel(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> pos(-0.5, 0.5), wt(0.05, 1.0);
  std::vector<Vec2> s;
  std::vector<double> w;
  for (int i = 0; i < n; ++i) {
    s.push_back({pos(rng), pos(rng)});
    w.push_back(wt(rng));
  }
  return make_kernel(s, w);
}

// More samples, closer to the filter: E1 falls towards 0 as a jittered
// pattern grows (box filter, equal weights, a fixed seed).
TEST(E1ClosedForm, DenseJitteredPatternsApproachZero) {
  const Metric metric(make_filter("box"), uniform_acuity(15));
  std::mt19937_64 rng(7);
  double previous = 1e9;
  for (int n : {1, 2, 4, 8, 16, 32}) {
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Vec2> s;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s.push_back({(i + u(rng)) / n - 0.5, (j + u(rng)) / n - 0.5});
    const double e2 = metric.kernel_error(make_kernel(s, std::vector<double>(n * n, 1.0))).e2;
    EXPECT_GT(e2, 0.0);
    EXPECT_LT(e2, previous) << n;
    previous = e2;
  }
  EXPECT_LT(previous, 0.05);  // 1024 samples
}

RC_GTEST_PROP(E2Invariance, UnderPermutationOfSamples, ()) {
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  const Kernel k = random_kernel(rng, *rc::gen::inRange(1, 30));
  std::vector<int> order(k.size());
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  Kernel shuffled;
  for (int i : order) {
    shuffled.x.push_back(k.x[i]);
    shuffled.y.push_back(k.y[i]);
    shuffled.w.push_back(k.w[i]);
  }
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  RC_ASSERT(std::abs(metric.kernel_error(k).e2 - metric.kernel_error(shuffled).e2) <= 1e-12);
}

// The default table is symmetric under theta -> -theta and theta -> theta + 90,
// so mirroring a kernel in x and turning it by 90 degrees leave E2 unchanged.
RC_GTEST_PROP(E2Invariance, UnderTheAcuityTablesSymmetries, ()) {
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  const Kernel k = random_kernel(rng, *rc::gen::inRange(1, 12));
  Kernel mirrored = k, turned = k;
  for (int i = 0; i < k.size(); ++i) {
    mirrored.x[i] = -k.x[i];
    turned.x[i] = -k.y[i];
    turned.y[i] = k.x[i];
  }
  for (const AcuityTable& table : {laine_aila_acuity(), uniform_acuity(15), linear_acuity(5)}) {
    const Metric metric(make_filter("mitchell"), table);
    const double e2 = metric.kernel_error(k).e2;
    RC_ASSERT(std::abs(metric.kernel_error(mirrored).e2 - e2) <= 1e-12);
    RC_ASSERT(std::abs(metric.kernel_error(turned).e2 - e2) <= 1e-12);
  }
}

// Mirrored P(4,1+,n) tiles: the four kernels are mirror images, so their E2 agree.
RC_GTEST_PROP(E2Invariance, EqualForTheKernelsOfAMirroredTile, ()) {
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  const int sites = *rc::gen::inRange(1, 6);
  std::vector<Vec2> base;
  for (int i = 0; i < sites; ++i) {
    // Inside, or on an edge: edges are shared consistently by mirroring.
    switch (*rc::gen::inRange(0, 3)) {
      case 0:
        base.push_back({u(rng), u(rng)});
        break;
      case 1:
        base.push_back({*rc::gen::element(-0.5, 0.5), u(rng)});
        break;
      default:
        base.push_back({u(rng), *rc::gen::element(-0.5, 0.5)});
    }
  }
  std::vector<double> w(sites, 1.0 / sites);
  const Pattern p = mirrored_tile_pattern("random", base, w);
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  const PatternError e = metric.evaluate(p);
  for (double k : e.kernel_e2) RC_ASSERT(std::abs(k - e.kernel_e2[0]) <= 1e-12);
}

// Large kernels on a dense table keep their sorted order from angle to
// angle: every term equals the closed form sorted afresh, to rounding (the
// sums run in another order), for any table, ties included.
RC_GTEST_PROP(E2LargeKernels, TheCarriedOrderGivesTheFreshlySortedTerms, ()) {
  const int n = *rc::gen::inRange(25, 150);
  const bool on_grid = *rc::gen::arbitrary<bool>();  // ties in the projections
  Kernel k;
  for (int i = 0; i < n; ++i) {
    const double x =
        on_grid ? *rc::gen::inRange(-4, 5) / 8.0 : *rc::gen::inRange(-500, 501) / 1000.0;
    const double y =
        on_grid ? *rc::gen::inRange(-4, 5) / 8.0 : *rc::gen::inRange(-500, 501) / 1000.0;
    k.x.push_back(x), k.y.push_back(y), k.w.push_back(1.0 / n);
  }
  const char* tables[] = {"uniform:step=1", "uniform:step=5", "linear:step=2", "laine-aila"};
  const Metric metric(make_filter("mitchell"), make_acuity(tables[*rc::gen::inRange(0, 4)]));
  std::vector<double> proj(n), values(metric.angle_count());
  metric.kernel_terms(k, proj, values);
  for (int a = 0; a < metric.angle_count(); ++a) {
    for (int j = 0; j < n; ++j) proj[j] = metric.cos(a) * k.y[j] - metric.sin(a) * k.x[j];
    const double fresh = metric.weight_sq(a) * e1_squared(metric.filter(), proj, k.w);
    RC_ASSERT(std::abs(values[a] - fresh) <= 1e-12 * std::max(fresh, 1e-3));
  }
}

TEST(E2Norm, OneIsTheMeanAndInfinityTheMaximum) {
  std::mt19937_64 rng(3);
  const Kernel k = random_kernel(rng, 5);
  const Metric max_metric(make_filter("mitchell"), uniform_acuity(10, 2.0));
  const Metric mean_metric(make_filter("mitchell"), uniform_acuity(10, 2.0), 1.0);
  const Metric p8(make_filter("mitchell"), uniform_acuity(10, 2.0), 8.0);
  const auto profile = max_metric.profile(k);
  double mean = 0, max = 0;
  for (double v : profile) {
    mean += v / profile.size();
    max = std::max(max, v);
  }
  EXPECT_NEAR(mean_metric.kernel_error(k).e2, mean, 1e-14);
  EXPECT_DOUBLE_EQ(max_metric.kernel_error(k).e2, max);
  EXPECT_GT(p8.kernel_error(k).e2, mean);
  EXPECT_LT(p8.kernel_error(k).e2, max);
}

// The L_p mean is computed scaled by its largest term: no p and no scale of
// the terms over- or underflows, and p -> infinity tends to the maximum.
TEST(E2Norm, LargeNormsAndTinyTermsStayFinite) {
  const std::vector<double> tiny = {1e-300, 4e-300, 2e-300};  // W^2 E1^2 per angle
  EXPECT_DOUBLE_EQ(combine_over_angles(tiny, Metric::kMaxNorm), 2e-150);
  EXPECT_NEAR(combine_over_angles(tiny, 1e6) / 2e-150, 1, 2e-6);  // (1/3)^(1/p)
  EXPECT_NEAR(combine_over_angles(tiny, 2), std::sqrt(7e-300 / 3), 1e-162);
  const std::vector<double> equal(180, 0.25);
  for (double p : {1.0, 4.0, 1000.0, 2000.0, 1e6})
    EXPECT_DOUBLE_EQ(combine_over_angles(equal, p), 0.5);
  EXPECT_EQ(combine_over_angles(std::vector<double>(4, 0.0), 8), 0.0);
}

TEST(E2Norm, RejectsNormsBelowOne) {
  EXPECT_THROW(Metric(make_filter("box"), laine_aila_acuity(), 0.5), Error);
  EXPECT_THROW(Metric(make_filter("box"), laine_aila_acuity(), std::nan("")), Error);
}

TEST(E2Profile, IsWeightTimesE1AtEachAngle) {
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  const Kernel k = make_kernel({{0.1, 0.2}, {-0.3, 0.05}}, {0.6, 0.4});
  const auto profile = metric.profile(k);
  ASSERT_EQ(profile.size(), 4u);
  // Edge angle 0: the normal is +y, so the projections are the y coordinates.
  EXPECT_NEAR(profile[0], 3.93 * e1_1d(metric.filter(), {0.2, 0.05}, {0.6, 0.4}), 1e-14);
  // Edge angle 90: the normal is -x.
  EXPECT_NEAR(profile[2], 3.93 * e1_1d(metric.filter(), {-0.1, 0.3}, {0.6, 0.4}), 1e-14);
}

// worst_term is the record-breaking scan with its 1e-12 tolerance (the first
// of near-ties, NaN skipped), whichever way it finds it (a shortcut on SIMD
// lanes where one value stands clear), on every code path: on values drawn
// to hold clear maxima, near-ties, exact ties, zeros, negatives, NaN and inf.
RC_GTEST_PROP(WorstTerm, IsTheScanWithItsTolerance, ()) {
  const auto scan = [](const std::vector<double>& v) {
    int worst = 0;
    double threshold = v.empty() ? 0 : v[0] * (1 + 1e-12);
    for (size_t a = 1; a < v.size(); ++a)
      if (v[a] > threshold) {
        worst = static_cast<int>(a);
        threshold = v[a] * (1 + 1e-12);
      }
    return worst;
  };
  const size_t n = *rc::gen::inRange<size_t>(0, 200);
  std::vector<double> v(n);
  for (double& x : v) {
    const int kind = *rc::gen::inRange(0, 100);
    if (kind < 75)
      x = *rc::gen::inRange(0, 1000) / 1001.0;  // below 1
    else if (kind < 90)
      x = 1 + 1e-13 * *rc::gen::inRange(-20, 20);  // near-ties at the top
    else if (kind < 93)
      x = 0;
    else if (kind < 96)
      x = -*rc::gen::inRange(1, 1000) / 1000.0;
    else if (kind < 98)
      x = std::nan("");
    else
      x = INFINITY;
  }
  if (n > 0 && *rc::gen::inRange(0, 4) == 0) v[*rc::gen::inRange<size_t>(0, n)] = 2;  // clear
  const int expected = scan(v);
  for (const int64_t target : simd_targets_here()) {  // the shortcut on every path
    pin_simd_target(target);
    const int found = Metric::worst_term(v);
    pin_simd_target(0);
    RC_ASSERT(found == expected);
  }
}

TEST(WorstTerm, TakesTheFirstOfNearTiesNotTheLargest) {
  EXPECT_EQ(Metric::worst_term(std::vector<double>{0.1, 1.0, 0.3, 1.0 + 5e-13, 0.2}), 1);
  EXPECT_EQ(Metric::worst_term(std::vector<double>{0.1, 1.0, 0.3, 1.0 + 5e-12, 0.2}), 3);
  EXPECT_EQ(Metric::worst_term(std::vector<double>{0.5, 0.5, 0.5, 0.5, 0.5}), 0);
  EXPECT_EQ(Metric::worst_term(std::vector<double>{NAN, 0.9, 2.0, 0.5, 0.1}), 0);
  EXPECT_EQ(Metric::worst_term(std::vector<double>{0.3, 0.9, 2.0, 0.5, 0.1}), 2);
}

}  // namespace
}  // namespace aapat
