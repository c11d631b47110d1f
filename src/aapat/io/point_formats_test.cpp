// The peers' formats: every format round-trips what it can hold, bad files
// are named, and the discrepancy of a UTK file equals that of the same points
// in aapat's CSV.
#include "aapat/io/point_formats.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstring>

#include "aapat/analyze/discrepancy.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/pattern_text.h"
#include "testing/cli_run.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

PointSets random_sets(bool many, bool float_exact) {
  const int count = many ? *rc::gen::inRange(1, 5) : 1;
  PointSets sets;
  for (int s = 0; s < count; ++s) {
    const int n = *rc::gen::inRange(1, 40);
    std::vector<Vec2> set;
    for (int i = 0; i < n; ++i) {
      // Any double in [0, 1], or one a float holds exactly for the float format.
      auto coordinate = [&] {
        const double v =
            *rc::gen::inRange<uint64_t>(0, 1ull << 53) / static_cast<double>(1ull << 53);
        return float_exact ? static_cast<double>(static_cast<float>(v)) : v;
      };
      const double x = coordinate(), y = coordinate();
      set.push_back({x, y});
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

RC_GTEST_PROP(PointFormats, EveryFormatRoundTripsExactly, ()) {
  for (const PointFormatInfo& f : point_formats()) {
    if (f.format == PointFormat::kPattern) continue;  // patterns: pattern_json_test
    const PointSets sets = random_sets(f.many_sets, f.format == PointFormat::kPspec);
    const PointSets back = parse_point_sets(format_point_sets(sets, f.format), f.format, "memory");
    RC_ASSERT(back == sets);
  }
}

TEST(PointFormats, UtkTextSeparatesSetsWithHashLinesAndSkipsLeadingComments) {
  const PointSets s =
      parse_point_sets("# made by utk\n0.1 0.2\n0.3 0.4\n#\n0.5 0.6\n", PointFormat::kUtk, "t.dat");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], (std::vector<Vec2>{{0.1, 0.2}, {0.3, 0.4}}));
  EXPECT_EQ(s[1], (std::vector<Vec2>{{0.5, 0.6}}));
}

TEST(PointFormats, UtkBinaryIsACountThenDoublePairsPerSet) {
  std::string bytes;
  auto put = [&](const void* p, size_t n) { bytes.append(static_cast<const char*>(p), n); };
  const uint32_t n = 2;
  const double v[4] = {0.25, 0.5, 0.75, 1.0};
  put(&n, 4);
  put(v, sizeof v);
  EXPECT_EQ(bytes.size(), 36u);
  const PointSets s = parse_point_sets(bytes, PointFormat::kUtkBinary, "t.bin");
  EXPECT_EQ(s, (PointSets{{{0.25, 0.5}, {0.75, 1.0}}}));
  EXPECT_EQ(format_point_sets(s, PointFormat::kUtkBinary), bytes);
}

TEST(PointFormats, SafariKeepsTheFirstTwoOfManyColumns) {
  EXPECT_EQ(parse_point_sets("0.1, 0.2, 0.9\n0.3, 0.4, 0.8\n", PointFormat::kSafari, "s.csv"),
            (PointSets{{{0.1, 0.2}, {0.3, 0.4}}}));
  EXPECT_EQ(format_point_sets({{{0.5, 0.25}}}, PointFormat::kSafari), "0.5, 0.25\n");
}

TEST(PointFormats, PsaStartsWithTheCount) {
  EXPECT_EQ(format_point_sets({{{0.5, 0.25}, {0.125, 1}}}, PointFormat::kPsa),
            "2\n0.5 0.25\n0.125 1\n");
}

TEST(PointFormats, BadFilesAreNamed) {
  using testing::error_message;
  EXPECT_EQ(error_message([] { parse_point_sets("3\n0.1 0.2\n", PointFormat::kPsa, "p.psa"); }),
            "point file p.psa: says 3 points but holds 1");
  EXPECT_EQ(error_message([] { parse_point_sets("0.1 1.5\n", PointFormat::kUtk, "u.dat"); }),
            "point file u.dat line 1: (0.1, 1.5) lies outside the unit square [0, 1] x [0, 1]");
  EXPECT_EQ(error_message([] { parse_point_sets("0.1 0.2 0.3\n", PointFormat::kUtk, "u.dat"); }),
            "point file u.dat line 1: expected 'x y', got '0.1 0.2 0.3'");
  const uint32_t huge = 1u << 30;
  std::string bin(reinterpret_cast<const char*>(&huge), 4);
  EXPECT_EQ(error_message([&] { parse_point_sets(bin, PointFormat::kUtkBinary, "u.bin"); }),
            "point file u.bin: set 1 says 1073741824 points but 0 bytes follow");
  EXPECT_EQ(error_message([] { parse_point_sets("abcde", PointFormat::kPspec, "p.f32"); }),
            "point file p.f32: 5 bytes is not a whole number of (x, y) float pairs");
  EXPECT_EQ(error_message([] {
              format_point_sets({{{0, 0}}, {{1, 1}}}, PointFormat::kPsa);
            }),
            "psa files hold one point set, not 2: write utk or utk-bin");
  EXPECT_EQ(error_message([] { point_format("a.txt"); }),
            "format: 'a.txt' has no extension of a point format (.csv, .dat, .bin, .psa, .f32, "
            ".json); name one: csv, safari, utk, utk-bin, psa, pspec, json");
  EXPECT_EQ(point_format("a.txt", "psa"), PointFormat::kPsa);
}

TEST(PointFormats, AUtkFileHasTheDiscrepancyOfTheSamePointsInCsv) {
  const std::vector<Vec2> points = generate_points("best-candidate", 256, 7);
  const std::string dat = testing::temp_path("points.dat"), csv = testing::temp_path("points.csv");
  save_point_sets({points}, dat);
  save_point_sets({points}, csv);
  const auto a = load_point_sets(dat).front(), b = load_point_sets(csv).front();
  EXPECT_EQ(l2_star_discrepancy(a), l2_star_discrepancy(b));
  EXPECT_EQ(star_discrepancy(a).upper, star_discrepancy(b).upper);
  EXPECT_EQ(edge_discrepancy(a).value, edge_discrepancy(b).value);
  EXPECT_EQ(l2_star_discrepancy(a), l2_star_discrepancy(points));
}

TEST(PatternText, RoundTripsAOnePixelPatternAndRefusesATile) {
  const Pattern rgss = catalog_pattern("rgss");
  const Pattern back = pattern_from_text(pattern_to_text(rgss), "dir/rgss.xyw");
  EXPECT_EQ(back.name, "rgss");
  EXPECT_EQ(back.sets, rgss.sets);
  EXPECT_EQ(back.weights, rgss.weights);
  EXPECT_EQ(testing::error_message([] { pattern_to_text(catalog_pattern("flipquad")); }),
            "pattern flipquad is P(4,1+,2): the x y weight text holds one pixel's samples and "
            "weights (P(1,1,n)); write it as .json");
  EXPECT_EQ(testing::error_message([] { pattern_from_text("0.1 0.2\n", "a.xyw"); }),
            "pattern file a.xyw line 1: expected 'x y weight', got 2 values");
}

}  // namespace
}  // namespace aapat
