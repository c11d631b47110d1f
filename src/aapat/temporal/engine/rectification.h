// History rectification: the reprojected history pulled into a box that the
// current frame's 3x3 neighbourhood spans, in YCoCg for colour (Karis 2014)
// and on the value itself for grey (whose YCoCg is (v, 0, 0)):
//  - box minmax: the neighbourhood's per-component minimum and maximum;
//    box variance: mean +- gamma sigma per component (Salvi 2016);
//  - clamp: each component clamped into the box (FSR 2's RectifyHistory);
//    clip: the history moved toward the box centre along the line between
//    them until it enters the box (Playdead's clip, as Bevy and Godot 4 do);
//    none: the history as it is.
#pragma once

#include <string>
#include <string_view>

namespace aapat {

enum class Rectification { none, clamp, clip };
enum class RectificationBox { minmax, variance };

Rectification parse_rectification(std::string_view name);  // none, clamp, clip
std::string_view rectification_name(Rectification r);
RectificationBox parse_rectification_box(std::string_view name);  // minmax, variance
std::string_view rectification_box_name(RectificationBox b);

// RGB <-> YCoCg (Y = R/4 + G/2 + B/4, Co = R/2 - B/2, Cg = -R/4 + G/2 - B/4).
void rgb_to_ycocg(const double* rgb, double* ycocg);
void ycocg_to_rgb(const double* ycocg, double* rgb);

// The history (n components, the space of the box) rectified in place
// against the neighbourhood's 9 colours (9 x n values, same space).
void rectify(Rectification r, RectificationBox box, double gamma, const double* neighbourhood,
             int n, double* history);

}  // namespace aapat
