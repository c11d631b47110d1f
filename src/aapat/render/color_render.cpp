#include "aapat/render/color_render.h"

#include <fmt/format.h>

#include <array>

namespace aapat {

bool is_colour(const Scene& scene) {
  return std::holds_alternative<MeshScene>(scene.shape);
}

Scene channel_scene(const Scene& scene, int c) {
  if (c < 0 || c > 2) throw Error(fmt::format("channel {}: expected 0, 1 or 2", c));
  Scene out = scene;
  if (auto* mesh = std::get_if<MeshScene>(&out.shape)) mesh->channel = c;
  return out;
}

Image render_channels(const Scene& scene,
                      const std::function<Image(const Scene&)>& render_channel) {
  if (!is_colour(scene)) return render_channel(scene);
  std::array<Image, 3> parts;
  for (int c = 0; c < 3; ++c)
    parts[static_cast<size_t>(c)] = render_channel(channel_scene(scene, c));
  Image out{parts[0].width, parts[0].height, parts[0].offset,
            std::vector<double>(3 * parts[0].values.size()), 3};
  for (size_t p = 0; p < parts[0].values.size(); ++p)
    for (size_t c = 0; c < 3; ++c) out.values[3 * p + c] = parts[c].values[p];
  return out;
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
