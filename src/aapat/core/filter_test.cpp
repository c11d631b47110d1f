#include "aapat/core/filter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/geometry.h"
#include "testing/error_message.h"
#include "testing/quadrature.h"

namespace aapat {
namespace {

using testing::integrate_pieces;

// Every named filter with its defaults, and a few with parameters.
std::vector<std::string> all_specs() {
  std::vector<std::string> specs;
  for (const auto& f : filter_registry().entries()) specs.push_back(f.info.name);
  specs.insert(specs.end(), {"mitchell:b=3/2,c=-1/4", "gaussian:sigma=0.3,radius=2", "box:width=2",
                             "tent:radius=1.5", "lanczos:lobes=2", "keys:a=-3/4"});
  return specs;
}

class EveryFilter : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryFilter, IntegratesToOne) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  EXPECT_NEAR(integrate_pieces([&](double x) { return f.value(x); }, -r, r, r / 8), 1.0, 1e-10);
}

TEST_P(EveryFilter, ZeroPastRadius) {
  const Filter f = make_filter(GetParam());
  for (double x : {f.radius() * (1 + 1e-9), f.radius() + 0.5, 100.0}) {
    EXPECT_EQ(f.value(x), 0.0) << x;
    EXPECT_EQ(f.value(-x), 0.0) << x;
  }
}

TEST_P(EveryFilter, StepResponseGoesFromZeroToOne) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  EXPECT_EQ(f.step_response(-r), 0.0);
  EXPECT_EQ(f.step_response(r), 1.0);
  EXPECT_DOUBLE_EQ(f.step_response(0), 0.5);
  EXPECT_NEAR(f.step_response(r * (1 - 1e-12)), 1.0, 1e-9);
  for (double a = -r; a <= r; a += r / 37)
    EXPECT_NEAR(f.step_response(a) + f.step_response(-a), 1.0, 1e-14) << a;
}

// The exact tables against the definition, integrated independently.
TEST_P(EveryFilter, StepResponseMatchesIntegralOfImpulseResponse) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  for (double a = -r; a <= r; a += r / 23) {
    const double numeric = integrate_pieces([&](double x) { return f.value(x); }, -r, a, r / 8);
    EXPECT_NEAR(f.step_response(a), numeric, 1e-10) << "a = " << a;
  }
}

TEST_P(EveryFilter, AbsMomentIsMeanDistance) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  for (double p : {0.0, 0.1, -0.37, 0.5, 1.0, r * 0.9, r, r + 0.7, -r - 2}) {
    const double numeric =
        integrate_pieces([&](double t) { return std::abs(p - t) * f.value(t); }, -r, r, r / 8);
    EXPECT_NEAR(f.abs_moment(p), numeric, 1e-10) << "p = " << p;
  }
}

TEST_P(EveryFilter, StepIntegralsMatchQuadrature) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  for (double a : {-r - 1, -r * 0.8, -0.2, 0.0, 0.3, r * 0.7, r, r + 0.5}) {
    const double lo = -r - 1;
    const double i1 = integrate_pieces([&](double x) { return f.step_response(x); }, lo, a, r / 8);
    const double i2 = integrate_pieces(
        [&](double x) { return f.step_response(x) * f.step_response(x); }, lo, a, r / 8);
    EXPECT_NEAR(f.step_integral(a), i1, 1e-10) << "a = " << a;
    EXPECT_NEAR(f.step_square_integral(a), i2, 1e-10) << "a = " << a;
  }
}

TEST_P(EveryFilter, HalfMeanDistanceMatchesQuadrature) {
  const Filter f = make_filter(GetParam());
  const double r = f.radius();
  const double numeric =
      integrate_pieces([&](double t) { return f.abs_moment(t) * f.value(t); }, -r, r, r / 8);
  EXPECT_NEAR(f.half_mean_distance(), numeric / 2, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Filters, EveryFilter, ::testing::ValuesIn(all_specs()),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return s;
                         });

// Spot values that pin conventions (Mitchell & Netravali 1988, Eq. 8).
TEST(FilterSpotValues, MitchellNetravali) {
  const Filter f = make_filter("mitchell");
  EXPECT_NEAR(f.value(0), (6 - 2.0 / 3) / 6, 1e-15);  // (6 - 2B) / 6
  EXPECT_NEAR(f.value(1), (1.0 / 3) / 6, 1e-15);      // B / 6
  EXPECT_NEAR(f.value(-1), (1.0 / 3) / 6, 1e-15);
  EXPECT_EQ(f.value(2), 0.0);
  EXPECT_EQ(f.radius(), 2.0);
}

TEST(FilterSpotValues, CatmullRomInterpolates) {
  const Filter f = make_filter("catmull-rom");
  EXPECT_NEAR(f.value(0), 1.0, 1e-15);
  EXPECT_NEAR(f.value(1), 0.0, 1e-15);
  const Filter keys = make_filter("keys");  // a = -1/2 is Catmull-Rom
  for (double x = 0; x < 2; x += 0.1) EXPECT_NEAR(keys.value(x), f.value(x), 1e-15);
}

TEST(FilterSpotValues, GossWuGaussianHalf) {
  // Height 1/2 at distance 1/2, and 1/512 at the 1.5 cut (Goss & Wu Sec. 3.3.3).
  const Filter f = make_filter("gaussian-half");
  EXPECT_NEAR(f.value(0.5) / f.value(0), 0.5, 1e-14);
  EXPECT_NEAR(f.value(1.5) / f.value(0), 1.0 / 512, 1e-15);
  EXPECT_EQ(f.radius(), 1.5);
}

TEST(FilterSpotValues, BoxAndTentClosedForms) {
  const Filter box = make_filter("box");
  EXPECT_NEAR(box.step_response(0.25), 0.75, 1e-15);
  EXPECT_NEAR(box.half_mean_distance(), 1.0 / 6, 1e-15);  // E|S-T| = 1/3 for U(-1/2, 1/2)
  const Filter tent = make_filter("tent");
  EXPECT_NEAR(tent.step_response(0.5), 1 - 0.125, 1e-15);  // 1 - (1 - a)^2 / 2
  EXPECT_NEAR(tent.abs_moment(0), 1.0 / 3, 1e-15);         // E|T| = 2 * int_0^1 t (1 - t)
}

TEST(FilterSpec, CanonicalNameFillsDefaults) {
  EXPECT_EQ(make_filter("mitchell").name(), "mitchell:b=1/3,c=1/3");
  EXPECT_EQ(make_filter(" mitchell : c = 0.5 ").name(), "mitchell:b=1/3,c=0.5");
  EXPECT_EQ(make_filter("gaussian:radius=2").name(), "gaussian:sigma=0.5,radius=2");
  EXPECT_EQ(make_filter("notch").name(), "notch");
}

TEST(FilterSpec, ParsesFractions) {
  EXPECT_DOUBLE_EQ(parse_number("1/3", "x"), 1.0 / 3);
  EXPECT_DOUBLE_EQ(parse_number("-1/4", "x"), -0.25);
  EXPECT_DOUBLE_EQ(parse_number(" 3/2 ", "x"), 1.5);
  EXPECT_DOUBLE_EQ(parse_number("+0.5", "x"), 0.5);
}

void expect_filter_error(const std::string& spec, const std::string& message) {
  EXPECT_EQ(testing::error_message([&] { make_filter(spec); }), message) << spec;
}

TEST(FilterSpec, RejectsBadSpecsWithClearMessages) {
  expect_filter_error(
      "mitchel",
      "unknown filter 'mitchel' (did you mean 'mitchell'?): known filters are box, tent, "
      "gaussian, gaussian-half, "
      "mitchell, notch, catmull-rom, keys, lanczos, lanczos-gaussian, blinn");
  expect_filter_error("mitchell:d=1", "filter mitchell: unknown parameter 'd=1' (it takes b, c)");
  expect_filter_error("notch:b=1",
                      "filter notch: unknown parameter 'b=1' (it takes no parameters)");
  expect_filter_error("gaussian:sigma=0", "filter gaussian: sigma = 0 is out of range [0.001, 16]");
  expect_filter_error("gaussian:sigma=nan", "filter gaussian: sigma: 'nan' is not a finite number");
  expect_filter_error("lanczos:lobes=2.5",
                      "filter lanczos: lobes = 2.5 must be a whole number in 1..16");
  expect_filter_error("mitchell:b=1/0", "filter mitchell: b: '1/0' divides by zero");
  expect_filter_error("box:width=abc", "filter box: width: 'abc' is not a finite number");
  // Narrower than 4096 pieces can tabulate to 1e-9 of the peak: refused, not wrong.
  expect_filter_error(
      "lanczos-gaussian:lobes=16,sigma=0.001",
      "filter lanczos-gaussian:lobes=16,sigma=0.001: too narrow to tabulate to 1e-09 of "
      "its peak with 4096 pieces (error 0.00051); widen it");
}

// A narrow Gaussian gets finer pieces and keeps its accuracy: its step
// response is the normal CDF, Phi(1) at one sigma.
TEST(FilterTabulation, NarrowGaussiansAreRefinedNotTruncated) {
  for (double sigma : {0.001, 0.003, 0.01, 0.05}) {
    const Filter f = make_filter("gaussian:sigma=" + std::to_string(sigma));
    EXPECT_NEAR(f.step_response(sigma), 0.5 * std::erfc(-1 / std::sqrt(2.0)), 1e-9) << sigma;
    EXPECT_NEAR(f.step_response(-2 * sigma), 0.5 * std::erfc(2 / std::sqrt(2.0)), 1e-9) << sigma;
    // NaN never reaches the table: it comes back as NaN.
    EXPECT_TRUE(std::isnan(f.abs_moment(std::nan(""))));
  }
}

}  // namespace
}  // namespace aapat
