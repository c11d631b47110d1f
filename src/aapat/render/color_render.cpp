#include "aapat/render/color_render.h"

#include <fmt/format.h>

namespace aapat {

bool is_colour(const Scene& scene) {
  return std::holds_alternative<MeshScene>(scene.shape);
}

int scene_channels(const Scene& scene) {
  return is_colour(scene) ? 3 : 1;
}

Image channel_image(const Image& image, int c) {
  if (c < 0 || c >= image.channels)
    throw Error(fmt::format("channel {} of an image of {} channel(s)", c, image.channels));
  Image out{image.width, image.height, image.offset, std::vector<double>(image.pixels()), 1};
  for (size_t p = 0; p < out.values.size(); ++p)
    out.values[p] = image.values[p * static_cast<size_t>(image.channels) + static_cast<size_t>(c)];
  return out;
}

}  // namespace aapat
