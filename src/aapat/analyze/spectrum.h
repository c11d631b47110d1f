// Fourier power spectra of point sets (periodograms), normalized so that
// white noise has expected power 1 away from the origin:
//   P(f) = |sum_j exp(-2 pi i f . p_j)|^2 / N.
// 2D: the points are a tile of the torus [0,1)^2, f runs over the integer
// frequencies -M/2 .. M/2-1 in x and y, evaluated exactly (no gridding of the
// points), in parallel over rows. 1D: points on a line, any frequencies.
#pragma once

#include <cstdint>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

// A spectrum image's side (frequencies per axis) on every face.
inline constexpr int kMinSpectrumSize = 8, kMaxSpectrumSize = 2048;

struct Spectrum2D {
  int size = 0;               // M: frequencies -M/2 .. M/2-1 on each axis
  std::vector<double> power;  // row v (from -M/2, bottom) then column u
  double at(int u, int v) const { return power[(v + size / 2) * size + (u + size / 2)]; }
};

Spectrum2D power_spectrum(const std::vector<Vec2>& points, int size);
// Adds `other` into `sum` (for averaging realizations).
void accumulate(Spectrum2D& sum, const Spectrum2D& other, double weight);

// The spectrum as grey levels, rows top-down (highest v first), grey = power / 2
// clamped to white, DC at the centre: what `aapat spectrum -o` writes.
std::vector<uint8_t> spectrum_grey_pixels(const Spectrum2D& s);

struct RadialProfile {
  std::vector<double> radius;         // integer |f| of each ring
  std::vector<double> power;          // mean power on the ring
  std::vector<double> anisotropy_db;  // 10 log10(variance / mean^2) on the ring
};
RadialProfile radial_average(const Spectrum2D& s);

// 1D periodogram at frequencies k * f_max / count, k = 0 .. count-1 (cycles
// per unit of x), in parallel over blocks of frequencies.
std::vector<double> power_spectrum_1d(const std::vector<double>& xs, int count, double f_max);

}  // namespace aapat
