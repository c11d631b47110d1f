// Colour renderings: a mesh scene renders in colour (Image::channels 3, its
// values R, G, B per pixel), every other scene in grey.
#pragma once

#include "aapat/render/renderer.h"

namespace aapat {

// Whether the scene has colour (a mesh scene).
bool is_colour(const Scene& scene);
// The channels its renderings have: 3 for a colour scene, else 1.
int scene_channels(const Scene& scene);

// Channel c of an image, as a grey image.
Image channel_image(const Image& image, int c);

}  // namespace aapat
