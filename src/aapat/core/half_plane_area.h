// The area of the unit square on one side of a line, in closed form: the
// edge discrepancy's measure of a half-plane, and the exact coverage a test
// of the renderer compares with.
#pragma once

namespace aapat {

// Area of {p in [0,1]^2 : p . n <= t} for the unit normal n = (cos phi, sin phi).
double half_plane_area(double phi, double t);
// The same with phi fixed: the normal's terms computed once (the edge
// discrepancy asks for N areas per direction).
class HalfPlaneArea {
 public:
  explicit HalfPlaneArea(double phi);
  double operator()(double t) const;

 private:
  double c_, s_, a_, b_, lo_, hi_, total_;
  bool negative_c_, negative_s_;
};

}  // namespace aapat
