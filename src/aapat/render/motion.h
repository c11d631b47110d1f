// Motion for any scene: a rigid motion of the image per frame, applied after
// the scene's own view, so that every scene render takes (built-in, scene
// file, mesh) moves the same way, and every pixel's motion vector is exact:
//   pan:dx=DX,dy=DY            DX, DY display pixels per frame;
//   rotate:deg=D,cx=X,cy=Y     D degrees per frame about (X, Y), the image
//                              centre by default;
//   orbit:deg=D                a mesh scene's camera turned D degrees per
//                              frame about its target, around its up axis
//                              (the motion vectors: each pixel's surface
//                              point projected by the earlier camera);
//   static                     no motion (every frame frame 0's scene).
// Frame f shows the scene moved f steps (f may be negative: the frames a
// warm-up renders before frame 0).
#pragma once

#include <string>
#include <string_view>

#include "aapat/core/spec.h"
#include "aapat/render/scene.h"

namespace aapat {

struct Motion {
  std::string spec = "static";  // canonical, for reports
  Vec2 pan{0, 0};               // pixels per frame
  double degrees = 0;           // per frame, about `centre`
  Vec2 centre{0, 0};
  double orbit_deg = 0;  // a mesh camera's yaw per frame
  bool moving() const { return pan.x != 0 || pan.y != 0 || degrees != 0 || orbit_deg != 0; }
};

// A step's largest displacement of any point of a width x height image
// must stay below this many image sides: a history that shares no pixel
// with the frame before is no history (an error, not a measurement).
inline constexpr double kMaxMotionPerFrame = 0.5;

using MotionRegistry = Registry<Motion, int, int>;
const MotionRegistry& motion_registry();
// Parses and checks a motion spec for a width x height image. Throws Error
// naming the problem (unknown kind or key, out of range, a step that moves
// points by half the image or more).
Motion make_motion(std::string_view spec, int width, int height);

// The scene at frame f: its view composed with f steps of the motion (an
// orbit: its camera turned). Throws Error for an orbit of a scene that is
// not a mesh.
Scene moved_scene(const Scene& scene, const Motion& motion, int frame);

// Where the point p of a frame was one frame earlier (the inverse of one
// step): what a motion vector points to. An image motion's alone.
Vec2 previous_point(const Motion& motion, Vec2 p);
// The same for any motion, given the scenes of the frame (`now`) and the one
// before: an orbit projects p's surface point through the earlier camera
// (the background, which is uniform, stays), and gives NaN where that point
// was hidden or behind the camera then (a disocclusion: no history).
Vec2 previous_point(const Motion& motion, const Scene& now, const Scene& before, Vec2 p);
// Whether a point from previous_point lies on a width x height image (pixel
// centres at integers, edges at -1/2 and side - 1/2): where a history exists.
// False for NaN (a disocclusion).
inline bool on_image(Vec2 q, int width, int height) {
  return q.x >= -0.5 && q.x <= width - 0.5 && q.y >= -0.5 && q.y <= height - 0.5;
}

}  // namespace aapat
