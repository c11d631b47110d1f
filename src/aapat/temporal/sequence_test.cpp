#include "aapat/temporal/sequence.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/temporal/sequence_generators.h"
#include "aapat/temporal/sequence_json.h"
#include "aapat/temporal/temporal_metrics.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

Vec2 offset(const Sequence& s, int f) {
  return s.frames[static_cast<size_t>(f)].sets[0][0];
}

// FSR 2's jitter: Halton(2, 3) from index 1, minus 1/2.
TEST(SequenceGenerators, HaltonStartsAtIndexOneLikeTheUpscalers) {
  const Sequence s = make_sequence("halton:frames=4");
  EXPECT_EQ(offset(s, 0).x, 0.0);  // h2(1) = 1/2
  EXPECT_DOUBLE_EQ(offset(s, 0).y, 1.0 / 3 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 1).x, 0.25 - 0.5);  // h2(2) = 1/4
  EXPECT_DOUBLE_EQ(offset(s, 1).y, 2.0 / 3 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 2).x, 0.75 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 2).y, 1.0 / 9 - 0.5);
  const Sequence zero = make_sequence("halton:frames=2,start=0");
  EXPECT_EQ(offset(zero, 0).x, -0.5);  // index 0: the pixel's corner
  EXPECT_DOUBLE_EQ(radical_inverse_of(11, 3), 2.0 / 3 + 0.0 / 9 + 1.0 / 27);  // 11 = 102 in base 3
}

TEST(SequenceGenerators, R2IsThePlasticNumbersLattice) {
  const double g = 1.32471795724474602596;
  EXPECT_NEAR(g * g * g, g + 1, 1e-15);
  const Sequence s = make_sequence("r2:frames=3");
  EXPECT_NEAR(offset(s, 0).x, std::fmod(0.5 + 1 / g, 1.0) - 0.5, 1e-15);
  EXPECT_NEAR(offset(s, 2).y, std::fmod(0.5 + 3 / (g * g), 1.0) - 0.5, 1e-15);
}

// Unscrambled Sobol: (0, 0), (1/2, 1/2), (1/4, 3/4), (3/4, 1/4), ...; Owen
// scrambling keeps every power-of-two prefix a (0, m, 2)-net, so 16 points
// are N-rooks in both axes, for any seed.
TEST(SequenceGenerators, SobolIsANetScrambledOrNot) {
  const Sequence plain = make_sequence("sobol:frames=4,seed=0");
  const std::vector<Vec2> expected{{0, 0}, {0.5, 0.5}, {0.25, 0.75}, {0.75, 0.25}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(offset(plain, i).x + 0.5, expected[static_cast<size_t>(i)].x);
    EXPECT_EQ(offset(plain, i).y + 0.5, expected[static_cast<size_t>(i)].y);
  }
  for (int seed : {1, 2, 77}) {
    const Sequence s = make_sequence(fmt::format("sobol:frames=16,seed={}", seed));
    std::set<int> xs, ys;
    for (int i = 0; i < 16; ++i) {
      xs.insert(static_cast<int>(std::floor((offset(s, i).x + 0.5) * 16)));
      ys.insert(static_cast<int>(std::floor((offset(s, i).y + 0.5) * 16)));
    }
    EXPECT_EQ(xs.size(), 16u) << seed;
    EXPECT_EQ(ys.size(), 16u) << seed;
  }
}

// White noise is the point generator's uniform points less 1/2, so the two
// faces of "random" with one seed are the same points.
TEST(SequenceGenerators, RandomIsThePointGeneratorsUniformPoints) {
  for (uint64_t seed : {0, 1, 9}) {
    const Sequence s = make_sequence(fmt::format("random:frames=18,seed={}", seed));
    const std::vector<Vec2> points = generate_points("random", 18, seed);
    ASSERT_EQ(s.period(), 18);
    for (int f = 0; f < 18; ++f) {
      EXPECT_EQ(offset(s, f).x, points[size_t(f)].x - 0.5) << seed << " " << f;
      EXPECT_EQ(offset(s, f).y, points[size_t(f)].y - 0.5) << seed << " " << f;
    }
  }
  EXPECT_NE(offset(make_sequence("random:seed=1"), 0).x,
            offset(make_sequence("random:seed=2"), 0).x);
}

// At R = 3/2 display centres fall at render offsets -1/3, 0, 1/3: nine
// frames visit each pair once and every three consecutive frames each offset
// once per axis; at R = 2, -1/4 and 1/4 in four frames.
TEST(SequenceGenerators, DisplayLatticeVisitsEveryDisplayPhaseInALatinOrder) {
  const Sequence s = make_sequence("display-lattice:ratio=1.5");
  ASSERT_EQ(s.period(), 9);
  std::set<std::pair<int, int>> pairs;
  for (int k = 0; k < 9; ++k) {
    const int i = static_cast<int>(std::lround(3 * offset(s, k).x)),
              j = static_cast<int>(std::lround(3 * offset(s, k).y));
    EXPECT_NEAR(offset(s, k).x, i / 3.0, 1e-12);
    EXPECT_NEAR(offset(s, k).y, j / 3.0, 1e-12);
    pairs.insert({i, j});
  }
  EXPECT_EQ(pairs.size(), 9u);
  for (int first : {0, 3, 6}) {
    std::set<int> xs, ys;
    for (int k = first; k < first + 3; ++k) {
      xs.insert(static_cast<int>(std::lround(3 * offset(s, k).x)));
      ys.insert(static_cast<int>(std::lround(3 * offset(s, k).y)));
    }
    EXPECT_EQ(xs.size(), 3u);
    EXPECT_EQ(ys.size(), 3u);
  }
  const Sequence two = make_sequence("display-lattice:ratio=2,frames=6");
  ASSERT_EQ(two.period(), 6);
  EXPECT_NEAR(offset(two, 0).x, -0.25, 1e-12);
  EXPECT_NEAR(offset(two, 1).x, 0.25, 1e-12);
  EXPECT_NEAR(offset(two, 4).x, -0.25, 1e-12);  // the cycle of four again
  EXPECT_NEAR(offset(two, 4).y, -0.25, 1e-12);
  EXPECT_THROW(make_sequence("display-lattice:ratio=0.5"), Error);
}

// FSR 2 computes int32_t(8 * ratio^2) in float: Quality 1.5 -> 18, Balanced
// 1.7 -> 23, Performance 2 -> 32, Ultra Performance 3 -> 72 (its table), and
// 1.3 -> 13 where ceil would give 14.
TEST(SequenceGenerators, UpscalerPhasesAreTruncatedAsTheSourceDoes) {
  EXPECT_EQ(upscaler_phase_count(1.5), 18);
  EXPECT_EQ(upscaler_phase_count(1.7), 23);
  EXPECT_EQ(upscaler_phase_count(2.0), 32);
  EXPECT_EQ(upscaler_phase_count(3.0), 72);
  EXPECT_EQ(upscaler_phase_count(1.3), 13);
  EXPECT_EQ(upscaler_phase_count(1280, 1920), 18);
  EXPECT_EQ(testing::error_parameter([] { upscaler_phase_count(0.5); }), "ratio");
  EXPECT_EQ(testing::error_parameter([] { upscaler_phase_count(std::nan("")); }), "ratio");
}

// Orderings keep the pattern's samples, one per frame; the rooks order's
// prefixes of 1, 2 and 4 samples of a 4x4 grid are N-rooks.
TEST(SequenceGenerators, OrderingsPermuteThePatternsSamples) {
  const Pattern grid = catalog_pattern("grid-4x4");
  for (const char* spec : {"rooks-order", "blue-noise-order"}) {
    const Sequence s = make_sequence(spec, grid);
    ASSERT_EQ(s.period(), 16) << spec;
    std::set<std::pair<double, double>> got, want;
    for (int f = 0; f < 16; ++f) got.insert({offset(s, f).x, offset(s, f).y});
    for (const Vec2 v : grid.sets[0]) want.insert({v.x, v.y});
    EXPECT_EQ(got, want) << spec;
  }
  const Sequence rooks = make_sequence("rooks-order", grid);
  std::vector<Vec2> points;
  for (int f = 0; f < 16; ++f)
    points.push_back({offset(rooks, f).x + 0.5, offset(rooks, f).y + 0.5});
  const std::vector<PrefixMeasure> m = prefix_measures(points);
  for (int prefix : {1, 2, 4}) {
    EXPECT_EQ(m[static_cast<size_t>(prefix - 1)].most_in_x, 1) << prefix;
    EXPECT_EQ(m[static_cast<size_t>(prefix - 1)].most_in_y, 1) << prefix;
  }
  const Sequence split = make_sequence("split:frames=4", grid);
  EXPECT_EQ(split.frames[0].sets[0].size(), 4u);
}

TEST(SequenceFile, RoundTripsByteForByteInBothForms) {
  const Pattern grid = catalog_pattern("grid-4x4");
  for (const Sequence& s : {make_sequence("halton:frames=16"), make_sequence("sobol:frames=8"),
                            make_sequence("msaa-alternating:samples=4,frames=2"),
                            make_sequence("split:frames=2", grid)}) {
    const std::string text = sequence_to_json(s);
    const Sequence back = sequence_from_json(text, "test");
    EXPECT_EQ(sequence_to_json(back), text);
    ASSERT_EQ(back.period(), s.period());
    for (int f = 0; f < s.period(); ++f)
      EXPECT_EQ(back.frames[static_cast<size_t>(f)].sets, s.frames[static_cast<size_t>(f)].sets);
  }
  EXPECT_NE(sequence_to_json(make_sequence("halton:frames=2")).find("\"jitter\""),
            std::string::npos);
}

TEST(SequenceFile, BadInputIsNamed) {
  using testing::error_message;
  const auto parse = [](std::string body) {
    return error_message([&] {
      sequence_from_json(R"({"format": "aapat-sequence", "version": 1, "name": "s", )" + body + "}",
                         "f.json");
    });
  };
  EXPECT_EQ(parse(R"("jitter": [])"), "sequence file f.json: jitter: expected a non-empty array");
  EXPECT_EQ(parse(R"("jitter": [[0, 0]], "frames": [])"),
            "sequence file f.json: give the frames as exactly one of \"jitter\" (one offset per "
            "frame) and \"frames\" (a pattern per frame)");
  EXPECT_EQ(parse(R"("jitter": [[0, 0.7]])").find("sequence file f.json: sequence s: frame 0:"),
            0u);
  EXPECT_EQ(parse(R"("jitter": [[0, "x"]])"),
            "sequence file f.json: jitter[0]: expected [x, y], the offset in pixels");
  std::string many = R"("jitter": [)";
  for (int i = 0; i <= kMaxSequenceFrames; ++i) many += i ? ", [0, 0]" : "[0, 0]";
  EXPECT_EQ(parse(many + "]"),
            "sequence file f.json: jitter: 1025 frames exceed the limit of 1024");
  // Frames of different families: a one-pixel frame and a 2x2 tile.
  const std::string one =
      R"({"tile": [1, 1], "footprint": "1", "sets": [[[0, 0]]], "kernels": [[1]]})";
  const std::string tile =
      R"({"tile": [2, 1], "footprint": "1", "sets": [[[0, 0]], [[0, 0]]], "kernels": [[1], [1]]})";
  EXPECT_NE(parse(R"("frames": [)" + one + ", " + tile + "]")
                .find("frame 1 is a 2x1 tile with footprint 1, frame 0 a 1x1 tile"),
            std::string::npos);
  EXPECT_EQ(parse(R"j("jitter": [[0, 0]], "family": "P(1,1,2)")j"),
            "sequence file f.json: family: the file says P(1,1,2) but its frames make P(1,1,1)");
  // NaN cannot be written in JSON; through the library it is refused by name.
  Sequence nan{"n", "", {jitter_frame({std::nan(""), 0}, "f")}, {}};
  EXPECT_NE(error_message([&] { validate(nan); }).find("sequence n: frame 0:"), std::string::npos);
  Sequence empty{"e", "", {}, {}};
  EXPECT_EQ(error_message([&] { validate(empty); }), "sequence e: it has no frames");
}

TEST(SequenceFile, AFailedWriteLeavesNoFile) {
  const auto dir = std::filesystem::temp_directory_path() / "aapat-sequence-file-test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "s.json").string();
  std::filesystem::remove(path);
  Sequence empty{"e", "", {}, {}};
  EXPECT_THROW(save_sequence_file(empty, path), Error);
  EXPECT_FALSE(std::filesystem::exists(path));
  save_sequence_file(make_sequence("r2:frames=4"), path);
  EXPECT_EQ(load_sequence_file(path).period(), 4);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace aapat
