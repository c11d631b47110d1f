// FLIP (Andersson, Nilsson, Akenine-Moller, Oskarsson, Astrom and Fairchild,
// "FLIP: A Difference Evaluator for Alternating Images", HPG 2020): the
// perceived difference between a reference and a test image when a viewer
// flips between them, per pixel in [0, 1]. The LDR measure:
//   1. sRGB to linear RGB to YyCxCz (the linearized CIELab opponent space);
//   2. each channel filtered by its contrast sensitivity function, a
//      Gaussian (achromatic, red-green) or a sum of two (blue-yellow), in
//      degrees of visual angle: `ppd` pixels per degree sets their width;
//   3. back to linear RGB clamped to the gamut, to CIELab, the Hunt
//      adjustment (a, b scaled by L / 100), the HyAB distance (|dL| + the
//      Euclidean distance of a, b), raised to qc = 0.7 and remapped to
//      [0, 1] with pc = 0.4 and pt = 0.95 of the largest distance, that from
//      green to blue;
//   4. edges and points of the luminance (first and second derivatives of a
//      Gaussian of 0.5 w ppd pixels, w = 0.082 degrees), their largest
//      difference over sqrt 2, raised to qf = 0.5;
//   5. FLIP = colour difference ^ (1 - feature difference).
// Written from the paper; the constants are the paper's.
#pragma once

#include <vector>

#include "aapat/analyze/color_image.h"

namespace aapat {

// Pixels per degree for a viewer `distance` metres from a screen `width`
// metres wide with `pixels` columns.
double pixels_per_degree(double distance, double pixels, double width);

// The paper's default observer: 0.7 m from a 0.7 m wide 3840-pixel screen
// (67.0 pixels per degree).
double default_pixels_per_degree();
inline constexpr double kMinPixelsPerDegree = 1, kMaxPixelsPerDegree = 1000;

inline constexpr int kFlipHistogramBuckets = 100;  // over [0, 1]

struct FlipResult {
  int width = 0, height = 0;
  std::vector<float> map;  // per pixel in [0, 1], rows from the top
  double mean = 0, min = 0, max = 0;
  // Weighted by the error itself, as FLIP's authors pool it: the value below
  // which lie 25, 50 and 75 per cent of the total error.
  double weighted_q1 = 0, weighted_median = 0, weighted_q3 = 0;
  std::vector<long long> histogram;  // pixels per bucket of width 1/kFlipHistogramBuckets
};

// The reference's half of FLIP at one ppd (its filtered colour and its
// features), computed once for every test image compared with it: a study
// compares one reference with dozens of patterns' renderings.
struct FlipReference {
  int width = 0, height = 0;
  double ppd = 0;
  std::vector<float> l, a, b, edge, point;  // per pixel, rows from the top
};

// Throws ParameterError ("ppd") when ppd is not in [kMinPixelsPerDegree,
// kMaxPixelsPerDegree], Error when the image is empty.
FlipReference prepare_flip_reference(const ColorImage& reference, double ppd);

// Throws Error when the sizes differ.
FlipResult flip(const FlipReference& reference, const ColorImage& test);

// Throws Error when the sizes differ or an image is empty, ParameterError
// ("ppd") when ppd is not in [kMinPixelsPerDegree, kMaxPixelsPerDegree].
FlipResult flip(const ColorImage& reference, const ColorImage& test, double ppd);

}  // namespace aapat
