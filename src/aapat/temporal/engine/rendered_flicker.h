// Rendered flicker, one definition for every TAA rendering (the linear
// mode's and the engine pipeline's): the mean absolute change of the
// per-pixel error (0-255 levels, every channel) from the previous frame,
// followed along the motion: pixel p's error against the previous frame's
// error where p's content was (previous_point, read bilinearly), over the
// pixels whose content was inside the image. Without motion (a static
// scene, or the built-in animations, whose objects move over a still
// background and so have no one motion field) it is the change at the same
// pixel. Following the motion leaves out the change that is only content
// moving past a pixel, which an eye tracking the motion does not see as
// flicker, and keeps the jitter's own instability.
#pragma once

#include <vector>

#include "aapat/render/motion.h"

namespace aapat {

// `error` and `previous`: levels per value, rows from the bottom, `channels`
// values per pixel.
// `now` and `before`: the frames' scenes (an orbit's motion vectors need them).
double rendered_flicker(const std::vector<int>& error, const std::vector<int>& previous, int width,
                        int height, int channels, const Motion& motion, const Scene& now,
                        const Scene& before);

}  // namespace aapat
