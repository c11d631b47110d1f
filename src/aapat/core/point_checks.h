// The checks every face applies to coordinates it is handed (files, the
// command line, Python arrays), with one wording: a point set lies in the
// unit square, a pixel's samples in the pixel, every coordinate finite.
#pragma once

#include <span>
#include <string_view>

#include "aapat/core/geometry.h"

namespace aapat {

// Throws Error naming `what` and the first bad point unless there is at
// least one point and every point is finite and in [0, 1] x [0, 1].
void check_unit_square(std::span<const Vec2> points, std::string_view what);

// Throws Error naming `what` and the first bad coordinate unless every
// coordinate (x, y interleaved) is finite and in [-0.5, 0.5].
void check_in_pixel(std::span<const double> xy, std::string_view what);

}  // namespace aapat
