#include "aapat/temporal/sequence/sequence_json.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "aapat/generate/catalog.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

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
