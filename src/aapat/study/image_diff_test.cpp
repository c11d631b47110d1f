#include "aapat/study/image_diff.h"

#include <gtest/gtest.h>

#include <string>

#include "aapat/core/geometry.h"
#include "aapat/io/png_image.h"

namespace aapat {
namespace {

std::string pair_file(const std::string& name) {
  return std::string(AAPAT_TESTDATA_DIR) + "/flip/" + name;
}

struct FlipPair {
  const char* reference;
  const char* test;
  double mean_67, mean_30;  // NVlabs/flip v1.6's C++ tool (testdata/flip/README.md)
};

// The mean FLIP of three committed pairs (a photograph's crop against its
// JPEG, synthetic colour ramps, an aapat rendering against its reference)
// agrees with the reference implementation's to its six printed digits, at
// the default 67 pixels per degree and at 30.
TEST(ImageDiff, FlipMeanIsTheReferenceImplementations) {
  const FlipPair pairs[] = {{"teaser-crop-ref.png", "teaser-crop-jpeg.png", 0.111973, 0.154376},
                            {"colour-ref.png", "colour-test.png", 0.780889, 0.773389},
                            {"zoneplate-ref.png", "zoneplate-msaa4.png", 0.107815, 0.105263}};
  for (const FlipPair& p : pairs) {
    const ColorImage ref = read_png_color(pair_file(p.reference), "reference").image;
    const ColorImage test = read_png_color(pair_file(p.test), "test").image;
    EXPECT_NEAR(image_diff(ref, test, default_pixels_per_degree()).flip.mean, p.mean_67, 1e-5)
        << p.test;
    EXPECT_NEAR(image_diff(ref, test, 30).flip.mean, p.mean_30, 1e-5) << p.test;
  }
}

// Alpha is ignored, as the reference tool ignores it: an RGBA copy of the
// test image gives the same FLIP, and the reader says it had alpha.
TEST(ImageDiff, AlphaIsIgnored) {
  const ColorImage ref = read_png_color(pair_file("colour-ref.png"), "reference").image;
  const PngColor plain = read_png_color(pair_file("colour-test.png"), "test");
  const PngColor rgba = read_png_color(pair_file("colour-test-rgba.png"), "test");
  EXPECT_FALSE(plain.had_alpha);
  EXPECT_TRUE(rgba.had_alpha);
  EXPECT_EQ(image_diff(ref, rgba.image, 67).flip.mean, image_diff(ref, plain.image, 67).flip.mean);
}

// RMSE and PSNR in closed form (on 8-bit levels, as files hold them): every
// channel one level off gives RMSE 1 and PSNR 20 log10 255; equal images
// have no PSNR, SSIM 1 and FLIP 0.
TEST(ImageDiff, ClassicMeasuresHaveTheirClosedForms) {
  ColorImage a{16, 12, std::vector<float>(16 * 12 * 3, 128.0f / 255)};
  ColorImage b{16, 12, std::vector<float>(16 * 12 * 3, 129.0f / 255)};
  const ImageDiff d = image_diff(a, b, 67);
  EXPECT_EQ(d.rmse, 1.0);
  EXPECT_DOUBLE_EQ(*d.psnr, 20 * std::log10(255.0));
  const ImageDiff same = image_diff(a, a, 67);
  EXPECT_EQ(same.rmse, 0);
  EXPECT_FALSE(same.psnr.has_value());
  EXPECT_DOUBLE_EQ(*same.ssim, 1.0);
  EXPECT_EQ(same.flip.mean, 0);
}

// A file that is not a PNG, a truncated one and a missing one are refused by
// name.
TEST(ImageDiff, BadFilesAreRefusedByName) {
  EXPECT_THROW(
      {
        try {
          read_png_color(pair_file("README.md"), "reference image");
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("not a PNG"), std::string::npos) << e.what();
          throw;
        }
      },
      Error);
  EXPECT_THROW(read_png_color(pair_file("missing.png"), "test image"), Error);
}

}  // namespace
}  // namespace aapat
