#include "cli/animation_options.h"
#include "cli/app.h"
#include "testing/cli_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace aapat {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::run;
using testing::slurp;
using testing::temp_path;

// Hasselgren Table 2's ordering on a small translating circle: centroid
// sampling deviates most, FLIPQUAD (scheme F) least of these three.
TEST(CliAnimate, TranslatingCircleOrdersThePatternsAsThePaper) {
  auto rmse = [](const char* pattern) {
    const CliRun r = run({"animate", "circle", "--pattern", pattern, "--size", "24", "--frames",
                          "6", "--reference-samples", "64", "--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["rmse"].get<double>();
  };
  const double centroid = rmse("centroid"), fliptri = rmse("hasselgren-a"),
               flipquad = rmse("hasselgren-f");
  EXPECT_GT(centroid, fliptri);
  EXPECT_GT(fliptri, flipquad);
  const std::string dir = temp_path("frames");
  ASSERT_EQ(run({"animate", "triangle", "--pattern", "rgss", "--size", "16", "--frames", "3",
                 "--reference-samples", "16", "--frames-dir", dir})
                .code,
            0);
  EXPECT_TRUE(fs::exists(dir + "/frame-0002.png"));
  EXPECT_EQ(run({"animate", "square", "--pattern", "rgss"}).code, 1);
}

// Frame files sort in frame order for any count: 4 digits up to 10,000
// frames, then as many as the last frame needs.
TEST(CliAnimate, FrameNamesSortForAnyCount) {
  EXPECT_EQ(frame_digits(1), 4);
  EXPECT_EQ(frame_digits(10000), 4);  // frame-9999 is the last
  EXPECT_EQ(frame_digits(10001), 5);  // frame-10000 needs frame-00000 .. before it
  EXPECT_EQ(frame_digits(1000001), 7);
}

TEST(CliAnimate, GifOfTheFrames) {
  const std::string gif = temp_path("a.gif");
  const CliRun r = run({"animate", "circle", "--pattern", "rgss", "--size", "12", "--frames", "3",
                        "--reference-samples", "4", "--gif", gif, "--no-cache"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(gif).substr(0, 6), "GIF89a");
  EXPECT_EQ(run({"animate", "circle", "--pattern", "rgss", "--gif", temp_path("a.png")}).code, 1);
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) {
    const CliRun m = run({"animate", "circle", "--pattern", "rgss", "--size", "12", "--frames", "2",
                          "--reference-samples", "4", "--mp4", temp_path("a.mp4")});
    EXPECT_EQ(m.code, 1);
    EXPECT_NE(m.err.find("needs ffmpeg on the PATH"), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(temp_path("a.mp4")));
  }
}

}  // namespace
}  // namespace aapat
