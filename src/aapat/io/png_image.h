// Greyscale PNG output through libpng, written whole or not at all.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace aapat {

// `pixels` is width x height bytes, row by row from the top.
std::string png_gray_bytes(int width, int height, const std::vector<uint8_t>& pixels);
void write_png_gray(const std::string& path, int width, int height,
                    const std::vector<uint8_t>& pixels);

}  // namespace aapat
