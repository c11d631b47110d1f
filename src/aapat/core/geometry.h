// The small vocabulary of types the rest of aapat speaks: points in a pixel's
// local frame and the error type every layer throws.
//
// Conventions (docs/conventions.md): a pixel's centre is the origin, the pixel
// is [-0.5, 0.5]^2, x grows right and y grows up.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace aapat {

struct Vec2 {
  double x = 0;
  double y = 0;

  friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
  friend bool operator==(Vec2 a, Vec2 b) = default;
};

// Distance under which two sample positions are the same physical sample.
inline constexpr double kSameSampleEps = 1e-9;

// |(dx, dy)|. std::hypot guards against an overflow that image coordinates
// never reach, at several times the cost, and a reference's scenes measure a
// billion distances. Both give Pythagorean triples exactly.
inline double vector_length(double dx, double dy) {
  return std::sqrt(dx * dx + dy * dy);
}

inline bool same_point(Vec2 a, Vec2 b) {
  return std::abs(a.x - b.x) <= kSameSampleEps && std::abs(a.y - b.y) <= kSameSampleEps;
}

// Every user-facing failure: the message names the offending field or value.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An error in one named input of a library call, a spec's parameter or a
// setting: what() is the parameter's name followed by the detail ("family
// P(3,1,4): s = 3 ..."), and the command line reports the same detail under
// the flag that gave the input ("--family P(3,1,4): s = 3 ...").
class ParameterError : public Error {
 public:
  ParameterError(std::string parameter, std::string detail)
      : Error(parameter + detail), parameter_(std::move(parameter)), detail_(std::move(detail)) {}
  const std::string& parameter() const { return parameter_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string parameter_, detail_;
};

inline constexpr double kPi = 3.14159265358979323846;
inline double radians(double degrees) {
  return degrees * (kPi / 180.0);
}

}  // namespace aapat
