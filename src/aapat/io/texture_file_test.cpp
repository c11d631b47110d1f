#include "aapat/io/texture_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "aapat/io/png_image.h"
#include "aapat/io/scene_json.h"
#include "aapat/render/surface.h"
#include "testing/cli_run.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

using testing::temp_path;

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// A 1 x 1 grey PNG with its header's width and height replaced (and the
// header's CRC recomputed, so that only the size is wrong).
std::string png_claiming(uint32_t width, uint32_t height) {
  std::string png = png_gray_bytes(1, 1, {7});
  for (int k = 0; k < 4; ++k) {
    png[16 + k] = static_cast<char>(width >> (24 - 8 * k));
    png[20 + k] = static_cast<char>(height >> (24 - 8 * k));
  }
  uint32_t crc = 0xffffffffu;  // CRC-32 of "IHDR" and its 13 bytes
  for (size_t i = 12; i < 29; ++i) {
    crc ^= static_cast<uint8_t>(png[i]);
    for (int b = 0; b < 8; ++b) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1)));
  }
  crc ^= 0xffffffffu;
  for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
  return png;
}

// A PNG's rows run from the top, a texture's from the bottom; 8-bit grey
// levels become v / 255.
TEST(TextureFile, ReadsAGreyPngBottomUp) {
  const std::string path = temp_path("t.png");
  write_png_gray(path, 3, 2, {0, 51, 102, 153, 204, 255});
  const Texture t = read_texture_png(path);
  ASSERT_EQ(t.width, 3);
  ASSERT_EQ(t.height, 2);
  EXPECT_EQ(t.at(0, 1), 0.0);  // the top row
  EXPECT_EQ(t.at(2, 1), 102 / 255.0);
  EXPECT_EQ(t.at(0, 0), 153 / 255.0);
  EXPECT_EQ(t.at(2, 0), 1.0);
  EXPECT_EQ(load_texture(path)->texture.texels, t.texels);
}

TEST(TextureFile, BadFilesAreNamed) {
  auto message = [](const std::string& spec) {
    return testing::error_message([&] { load_texture(spec); });
  };
  EXPECT_NE(message(temp_path("missing.png")).find("no such file"), std::string::npos);
  const std::string text = temp_path("text.png");
  write_bytes(text, "this is not an image");
  EXPECT_NE(message(text).find("texture file '" + text + "': not a PNG image"), std::string::npos);
  // A PNG whose header claims 100000 x 1 pixels: refused before decoding.
  const std::string big = temp_path("big.png");
  write_bytes(big, png_claiming(100000, 1));
  EXPECT_EQ(message(big),
            "texture file '" + big +
                "': 100000x1 pixels; at most 8192 per side and 67108864 in all (docs/limits.md)");
  // A header of zero width: libpng itself refuses it.
  const std::string empty = temp_path("zero.png");
  write_bytes(empty, png_claiming(0, 5));
  EXPECT_NE(message(empty).find("texture file '" + empty + "': cannot decode it (Invalid IHDR"),
            std::string::npos)
      << message(empty);
  EXPECT_NE(message("checker:cells=0").find("cells"), std::string::npos);
  EXPECT_NE(message("marble").find("unknown texture 'marble'"), std::string::npos);
}

TEST(TextureFile, SceneFilesCarryTexturedPolygons) {
  const ShapesScene s = scene_from_json(R"({"shapes": [
      {"polygon": [[0, 0], [8, 0], [8, 8], [0, 8]], "uv": [[0, 0], [1, 0], [1, 1], [0, 1]],
       "w": [1, 1, 2, 2], "texture": "checker:cells=2,size=8", "grey": 0.5}]})",
                                        "s.json");
  ASSERT_TRUE(s.textured);
  const Scene scene = s;
  EXPECT_EQ(shade(scene, {1, 1}), 0.5);  // a white texel, half grey
  EXPECT_EQ(shade(scene, {7, 1}), 0.0);  // a black one
  auto message = [](const char* text) {
    return testing::error_message([&] { scene_from_json(text, "s.json"); });
  };
  EXPECT_EQ(message(R"({"shapes": [{"polygon": [[0,0],[1,0],[0,1]], "uv": [[0,0],[1,0]]}]})"),
            "scene file s.json: shapes[0].uv: expected 3 [u, v] pairs, one per vertex");
  EXPECT_EQ(
      message(R"({"shapes": [{"polygon": [[0,0],[1,0],[0,1]], "uv": [[0,0],[1,0],[0,1e999]]}]})")
          .substr(0, 33),
      "scene file s.json: not valid JSON");
  EXPECT_EQ(
      message(R"({"shapes": [{"polygon": [[0,0],[1,0],[0,1]], "uv": [[0,0],[1,0],[0,"x"]]}]})"),
      "scene file s.json: shapes[0].uv[2][1]: expected a number");
  EXPECT_EQ(
      message(
          R"({"shapes": [{"polygon": [[0,0],[4,0],[1,1],[0,4]], "uv": [[0,0],[1,0],[1,1],[0,1]]}]})"),
      "scene file s.json: shapes[0].polygon: a textured polygon must be convex (its texture "
      "coordinates are interpolated over the fan from its first vertex)");
  EXPECT_EQ(
      message(
          R"({"shapes": [{"polygon": [[0,0],[1,0],[0,1]], "uv": [[0,0],[1,0],[0,1]], "w": [1, 0, 1]}]})"),
      "scene file s.json: shapes[0].w[1]: 0 is outside [1e-06, 1000000]");
  EXPECT_NE(
      message(
          R"({"shapes": [{"polygon": [[0,0],[1,0],[0,1]], "uv": [[0,0],[1,0],[0,1]], "texture": "none.png"}]})")
          .find("shapes[0].texture: cannot read texture file 'none.png': no such file"),
      std::string::npos);
}

TEST(TextureFile, TexturesGoWhereTheyFit) {
  const Scene board = resolve_scene("checkerboard", 32, 32, "stripes");
  EXPECT_TRUE(has_texture(board));
  EXPECT_NE(testing::error_message([] {
              resolve_scene("spiral", 32, 32, "stripes");
            }).find("texture stripes: this scene has no texture coordinates"),
            std::string::npos);
  const std::string file = temp_path("uv.json");
  write_bytes(file, R"({"shapes": [{"polygon": [[0,0],[9,0],[0,9]], "uv": [[0,0],[1,0],[0,1]]}]})");
  EXPECT_NE(testing::error_message([&] {
              resolve_scene(file, 32, 32);
            }).find("shapes[0] has texture coordinates but no texture"),
            std::string::npos);
  EXPECT_TRUE(has_texture(resolve_scene(file, 32, 32, "checker")));
}

}  // namespace
}  // namespace aapat
