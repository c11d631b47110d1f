// Editing a pattern one sample at a time, as the explorer page's drag and
// weight fields do (web/): every edit returns a valid pattern or throws Error
// naming what is wrong.
//
// Samples are physical: a sample shared on a pixel border (a '+' footprint)
// is listed by every pixel whose closed square holds it, and moving it moves
// every copy. A sample dropped on a border becomes shared: its neighbours
// list it too and the footprint gains its '+', so n (the samples each pixel
// pays for) falls. A shared sample dragged off the border stops being shared.
#pragma once

#include "aapat/core/pattern.h"

namespace aapat {

// How close to a border (in pixels) a dropped sample snaps onto it.
inline constexpr double kBorderSnap = 0.02;

// Sample `index` of set `set` moved to `to` (that pixel's local frame, clamped
// to the closed pixel; within kBorderSnap of a border it lands on the border,
// shared). When which samples each kernel reads is unchanged, the weights are
// kept; otherwise every kernel's weights become equal (the new reads have no
// weight of their own yet). lattice > 0: `to` is first rounded to the
// 1/lattice grid (16: programmable MSAA), so ±8/16 is the border.
Pattern move_sample(const Pattern& p, int set, int index, Vec2 to, int lattice = 0);

// Kernel `kernel`'s weight `index` set to `value`, the kernel's other weights
// scaled so that they still sum to 1 (shared equally when they were all 0).
Pattern set_weight(const Pattern& p, int kernel, int index, double value);

}  // namespace aapat
