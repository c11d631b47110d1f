#include "aapat/io/gif_animation.h"

#include <gtest/gtest.h>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

TEST(GifAnimation, RoundTripsEveryGreyLevelOfEveryFrame) {
  GreyFrames f{17, 15, 8, {}};
  for (int k = 0; k < 3; ++k) {
    std::vector<uint8_t> px(17 * 15);
    for (size_t i = 0; i < px.size(); ++i) px[i] = static_cast<uint8_t>((i * 7 + k * 91) % 256);
    f.frames.push_back(px);
  }
  const std::string bytes = gif_bytes(f);
  EXPECT_EQ(bytes.substr(0, 6), "GIF89a");
  EXPECT_NE(bytes.find("NETSCAPE2.0"), std::string::npos);  // loops
  const GreyFrames back = frames_from_gif(bytes);
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 15);
  EXPECT_EQ(back.frames, f.frames);
  EXPECT_THROW(gif_bytes(GreyFrames{0, 5, 8, {{}}}), Error);
  EXPECT_THROW(frames_from_gif("GIF89a garbage"), Error);
}

}  // namespace
}  // namespace aapat
