#include "aapat/render/image_flip.h"

#include <algorithm>

#include "aapat/render/image_error.h"

namespace aapat {

float stored_value(double v) {
  return static_cast<float>(grey_level(v)) / 255.0f;
}

ColorImage color_image(const Image& image, ColorLevels levels) {
  const auto value = [levels](double v) {
    return levels == ColorLevels::kStored ? stored_value(v)
                                          : static_cast<float>(std::clamp(v, 0.0, 1.0));
  };
  ColorImage c{image.width, image.height,
               std::vector<float>(static_cast<size_t>(image.width) * image.height * 3)};
  for (int j = 0; j < image.height; ++j)  // the renderer's row 0 is the bottom
    for (int i = 0; i < image.width; ++i) {
      const size_t k = (static_cast<size_t>(j) * image.width + i) * image.channels;
      float* out = &c.rgb[3 * (static_cast<size_t>(image.height - 1 - j) * image.width + i)];
      for (size_t ch = 0; ch < 3; ++ch)  // grey: R = G = B
        out[ch] = value(image.values[k + (image.channels == 3 ? ch : 0)]);
    }
  return c;
}

double flip_mean(const Image& image, const Image& reference) {
  return flip(color_image(reference), color_image(image), default_pixels_per_degree()).mean;
}

FlipReference flip_reference(const Image& reference) {
  return prepare_flip_reference(color_image(reference), default_pixels_per_degree());
}

double flip_mean(const Image& image, const FlipReference& reference) {
  return flip(reference, color_image(image)).mean;
}

}  // namespace aapat
