// Colour renderings of a mesh scene: each channel is a grey scene
// (MeshScene::channel), rendered by the same path as every grey scene with
// the same samples, and the three images interleave into one of three
// channels. A grey scene renders as itself.
#pragma once

#include <functional>

#include "aapat/render/renderer.h"

namespace aapat {

// Whether the scene has colour (a mesh scene).
bool is_colour(const Scene& scene);

// The scene's channel c (0 red, 1 green, 2 blue); a grey scene is returned as is.
Scene channel_scene(const Scene& scene, int c);

// `render_channel` applied to each channel of a colour scene, the images
// interleaved (channels = 3); applied once to a grey scene.
Image render_channels(const Scene& scene, const std::function<Image(const Scene&)>& render_channel);

// Channel c of an image, as a grey image.
Image channel_image(const Image& image, int c);

}  // namespace aapat
