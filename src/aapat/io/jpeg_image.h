// JPEG images through libjpeg-turbo, read as colour images: glTF 2.0 allows
// PNG and JPEG base-colour textures, and OBJ materials name JPEGs often.
#pragma once

#include <string>
#include <string_view>

#include "aapat/analyze/color_image.h"
#include "aapat/io/png_image.h"

namespace aapat {

// Whether the bytes start as a JPEG file does (FF D8 FF).
bool is_jpeg(std::string_view bytes);

// Decodes a baseline or progressive JPEG, grey or colour, into sRGB values;
// the size is checked against `limits` (io/png_image.h) before decoding. Throws Error naming `path`
// and what it is (`what`).
ColorImage decode_jpeg(std::string_view bytes, const std::string& path, const std::string& what,
                       const ImageLimits& limits = kColorImageLimits);

}  // namespace aapat
